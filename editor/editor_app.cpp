#include "editor/editor_app.hpp"

#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>

#include "player/touch_event.hpp"
#include "storage/image_io.hpp"

namespace vimg::editor {
namespace {

constexpr double kFramePeriodS = 1.0 / 60.0;
// Idle: after this many frames without input (ImGui settles hover and popup state in a frame or
// two) the editor stops drawing until an event arrives, waking at kIdleWakeMs for autosave and
// status. Playing mode draws continuously (the oscilloscope and the finger trail move).
constexpr int kSettleFrames = 3;
constexpr int kIdleWakeMs = 250;
constexpr float kToolsWidth = 210.0f;
constexpr float kPropertiesWidth = 330.0f;
constexpr float kStatusHeight = 26.0f;
constexpr float kScopeHeight = 150.0f;

std::filesystem::path config_dir() {
  if (const char* c = std::getenv("XDG_CONFIG_HOME"); c && *c) return std::filesystem::path(c) / "vimg-editor";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".config" / "vimg-editor";
  return std::filesystem::temp_directory_path() / "vimg-editor";
}

Image new_image() {
  Image image;
  image.width_mm = 100.0;
  image.height_mm = 100.0;
  Meta meta;
  meta.tool = ToolInfo{"vimg-editor", VIMG_VERSION, {}};
  image.meta = meta;
  return image;
}

std::string join_diagnostics(const std::vector<Diagnostic>& diagnostics) {
  std::string out;
  for (const Diagnostic& d : diagnostics) {
    if (!out.empty()) out += "\n";
    out += d.to_string();
  }
  return out;
}

}  // namespace

EditorApp::EditorApp(EditorOptions options)
    : options_(std::move(options)),
      doc_(new_image()),
      recent_(config_dir() / "recent.txt"),
      recovery_(options_.recovery_dir.empty() ? RecoveryStore::default_dir()
                                              : std::filesystem::path(options_.recovery_dir)) {}

EditorApp::~EditorApp() { shutdown_window(); }

bool EditorApp::init_window() {
  SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "1");
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
    std::fprintf(stderr, "vimg-editor: cannot open a window: %s\n", SDL_GetError());
    return false;
  }
  window_ = SDL_CreateWindow("vimg-editor", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, options_.width_px,
                             options_.height_px, SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (!window_) {
    std::fprintf(stderr, "vimg-editor: cannot open a window: %s\n", SDL_GetError());
    return false;
  }
  renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED);
  if (!renderer_) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  if (!renderer_) {
    std::fprintf(stderr, "vimg-editor: cannot create a renderer: %s\n", SDL_GetError());
    return false;
  }
  double px_per_mm = options_.px_per_mm;
  if (px_per_mm <= 0) {
    float hdpi = 0, vdpi = 0;
    const int display = SDL_GetWindowDisplayIndex(window_);
    px_per_mm = (SDL_GetDisplayDPI(display < 0 ? 0 : display, nullptr, &hdpi, &vdpi) == 0 && hdpi > 30 && hdpi < 1000)
                    ? hdpi / 25.4
                    : 96.0 / 25.4;
  }
  view_ = Viewport(px_per_mm);
  view_.set_zoom(options_.zoom);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; nothing to remember
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0.0f;
  ImGui_ImplSDL2_InitForSDLRenderer(window_);
  ImGui_ImplSDLRenderer_Init(renderer_);
  return true;
}

void EditorApp::shutdown_window() {
  if (play_) play_->stop();
  if (ImGui::GetCurrentContext()) {
    ImGui_ImplSDLRenderer_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
  }
  if (renderer_) SDL_DestroyRenderer(renderer_);
  if (window_) SDL_DestroyWindow(window_);
  renderer_ = nullptr;
  window_ = nullptr;
  SDL_Quit();
}

int EditorApp::run() {
  if (!init_window()) return 1;
  offer_recovery();  // first: opening the file must not drop the work of a crashed session
  if (!options_.file.empty() && !open_file(options_.file)) {
    std::fprintf(stderr, "%s\n", error_message_.c_str());
  }
  refresh_library();
  if (options_.play_at_start) set_play_mode(true);

  std::vector<double> frame_times_s;
  double next_frame_s = monotonic_s();
  int frames = 0;
  while (!quit_) {
    const double t0 = monotonic_s();
    frame();
    ++frames;
    // Key releases held back from the frame that saw the press (see dispatch()).
    keys_pressed_this_frame_.clear();
    std::vector<SDL_Event> held = std::move(held_events_);
    held_events_.clear();
    for (const SDL_Event& e : held) dispatch(e);
    if (options_.benchmark_frames > 0) {
      frame_times_s.push_back(monotonic_s() - t0);
      SDL_Event e;
      while (SDL_PollEvent(&e)) dispatch(e);
      if (frames >= options_.benchmark_frames) break;
      continue;
    }
    ++frames_since_input_;
    if (!play_mode_ && frames_since_input_ > kSettleFrames && held_events_.empty()) {
      // Nothing moves: sleep until the user does something, waking only to autosave. A frame is
      // drawn again for an event or for a new status line (e.g. "autosaved").
      SDL_Event e;
      bool event = false;
      while (!quit_ && !(event = SDL_WaitEventTimeout(&e, kIdleWakeMs) != 0)) {
        const std::string before = status_;
        autosave_if_due();
        if (status_ != before) break;
      }
      if (event) {
        frames_since_input_ = 0;
        dispatch(e);
        while (SDL_PollEvent(&e)) dispatch(e);
      }
      next_frame_s = monotonic_s();
      continue;
    }
    next_frame_s += kFramePeriodS;
    double now = monotonic_s();
    if (next_frame_s < now) next_frame_s = now + kFramePeriodS;
    // Handle events the moment they arrive (playing mode pushes touches from here), then draw.
    while (!quit_ && (now = monotonic_s()) < next_frame_s) {
      SDL_Event e;
      const int wait_ms = std::max(1, static_cast<int>((next_frame_s - now) * 1000.0));
      if (SDL_WaitEventTimeout(&e, wait_ms)) {
        frames_since_input_ = 0;
        dispatch(e);
        while (SDL_PollEvent(&e)) dispatch(e);
      }
    }
  }
  if (play_mode_) set_play_mode(false);
  if (!frame_times_s.empty()) {
    std::sort(frame_times_s.begin(), frame_times_s.end());
    const double mean = std::accumulate(frame_times_s.begin(), frame_times_s.end(), 0.0) /
                        static_cast<double>(frame_times_s.size());
    const auto pct = [&](double p) {
      return frame_times_s[std::min(frame_times_s.size() - 1, static_cast<std::size_t>(p * static_cast<double>(frame_times_s.size())))];
    };
    SDL_RendererInfo info{};
    SDL_GetRendererInfo(renderer_, &info);
    std::printf("benchmark: renderer=%s primitives=%zu frames=%zu frame_ms mean=%.2f p50=%.2f p99=%.2f max=%.2f fps=%.1f\n",
                info.name ? info.name : "?", doc_.image().children.size(), frame_times_s.size(), mean * 1e3, pct(0.5) * 1e3, pct(0.99) * 1e3,
                frame_times_s.back() * 1e3, 1.0 / mean);
  } else {
    recovery_.discard();  // a clean exit: the user has chosen what to keep
  }
  return 0;
}

void EditorApp::dispatch(const SDL_Event& event) {
  // Dear ImGui 1.86 samples key state once per frame: a press and its release in the same frame
  // would be lost (fast typists, scripted input). The release waits for the next frame.
  if (event.type == SDL_KEYDOWN) keys_pressed_this_frame_.push_back(event.key.keysym.scancode);
  if (event.type == SDL_KEYUP &&
      std::find(keys_pressed_this_frame_.begin(), keys_pressed_this_frame_.end(), event.key.keysym.scancode) !=
          keys_pressed_this_frame_.end()) {
    held_events_.push_back(event);
    return;
  }
  handle_event(event);
}

void EditorApp::handle_event(const SDL_Event& event) {
  ImGui_ImplSDL2_ProcessEvent(&event);
  if (event.type == SDL_KEYDOWN || event.type == SDL_KEYUP) {
    // The modifiers as of this event (the backend reads SDL's current state, which may be later).
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = (event.key.keysym.mod & KMOD_CTRL) != 0;
    io.KeyShift = (event.key.keysym.mod & KMOD_SHIFT) != 0;
    io.KeyAlt = (event.key.keysym.mod & KMOD_ALT) != 0;
  }
  if (play_mode_) handle_play_input(event);
  switch (event.type) {
    case SDL_QUIT: request(PendingAction::quit); break;
    case SDL_WINDOWEVENT:
      if (event.window.event == SDL_WINDOWEVENT_CLOSE) request(PendingAction::quit);
      break;
    case SDL_KEYDOWN:
      if (!ImGui::GetIO().WantTextInput) handle_shortcut(event.key);
      break;
    default: break;
  }
}

void EditorApp::handle_play_input(const SDL_Event& event) {
  if (!play_ || !play_->playing()) return;
  const double now = monotonic_s();
  auto inside = [&](float x, float y) {
    return x >= canvas_x_ && y >= canvas_y_ && x < canvas_x_ + canvas_w_ && y < canvas_y_ + canvas_h_;
  };
  auto mm = [&](float x, float y) { return view_.to_mm(Point2Px{x, y}); };
  const bool popup = any_popup_open_;
  switch (event.type) {
    case SDL_MOUSEBUTTONDOWN:
      if (event.button.which == SDL_TOUCH_MOUSEID || event.button.button != SDL_BUTTON_LEFT || popup) break;
      if (inside(static_cast<float>(event.button.x), static_cast<float>(event.button.y))) {
        const Point2Mm p = mm(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
        play_->touch(0, TouchPhase::down, p.x_mm, p.y_mm, now);
        play_finger_down_ = true;
      }
      break;
    case SDL_MOUSEMOTION:
      if (event.motion.which == SDL_TOUCH_MOUSEID || !play_finger_down_) break;
      {
        const Point2Mm p = mm(static_cast<float>(event.motion.x), static_cast<float>(event.motion.y));
        play_->touch(0, TouchPhase::move, p.x_mm, p.y_mm, now);
      }
      break;
    case SDL_MOUSEBUTTONUP:
      if (event.button.which == SDL_TOUCH_MOUSEID || event.button.button != SDL_BUTTON_LEFT || !play_finger_down_) break;
      {
        const Point2Mm p = mm(static_cast<float>(event.button.x), static_cast<float>(event.button.y));
        play_->touch(0, TouchPhase::up, p.x_mm, p.y_mm, now);
        play_finger_down_ = false;
      }
      break;
    case SDL_FINGERDOWN:
    case SDL_FINGERMOTION:
    case SDL_FINGERUP: {
      int w = 0, h = 0;
      SDL_GetWindowSize(window_, &w, &h);
      const float x = event.tfinger.x * static_cast<float>(w);
      const float y = event.tfinger.y * static_cast<float>(h);
      // Finger 0 is the mouse; touches take 1..9 by their order of arrival.
      const int finger = 1 + static_cast<int>(event.tfinger.fingerId % 9);
      const Point2Mm p = mm(x, y);
      if (event.type == SDL_FINGERDOWN) {
        if (inside(x, y) && !popup) play_->touch(finger, TouchPhase::down, p.x_mm, p.y_mm, now);
      } else if (event.type == SDL_FINGERMOTION) {
        if (play_->fingers()[static_cast<std::size_t>(finger)]) play_->touch(finger, TouchPhase::move, p.x_mm, p.y_mm, now);
      } else if (play_->fingers()[static_cast<std::size_t>(finger)]) {
        play_->touch(finger, TouchPhase::up, p.x_mm, p.y_mm, now);
      }
      break;
    }
    default: break;
  }
}

void EditorApp::handle_shortcut(const SDL_KeyboardEvent& key) {
  const SDL_Keycode k = key.keysym.sym;
  const bool ctrl = (key.keysym.mod & KMOD_CTRL) != 0;
  const bool shift = (key.keysym.mod & KMOD_SHIFT) != 0;
  const bool alt = (key.keysym.mod & KMOD_ALT) != 0;
  if (any_popup_open_) return;  // dialogs take the keyboard
  if (k == SDLK_F5 || k == SDLK_TAB) {
    set_play_mode(!play_mode_);
    return;
  }
  if (ctrl) {
    switch (k) {
      case SDLK_n: request(PendingAction::new_document); return;
      case SDLK_o: path_prompt_ = PathPrompt::open; path_prompt_opening_ = true; path_buffer_[0] = 0; return;
      case SDLK_s:
        if (shift || document_path_.empty()) {
          path_prompt_ = PathPrompt::save_as;
          path_prompt_opening_ = true;
          std::snprintf(path_buffer_, sizeof path_buffer_, "%s", document_path_.c_str());
        } else {
          save();
        }
        return;
      case SDLK_q: request(PendingAction::quit); return;
      case SDLK_0: view_.set_zoom(1.0); view_.reset_pan(); return;
      case SDLK_EQUALS:
      case SDLK_PLUS: view_.zoom_at(1.25, canvas_x_ + canvas_w_ / 2, canvas_y_ + canvas_h_ / 2); return;
      case SDLK_MINUS: view_.zoom_at(0.8, canvas_x_ + canvas_w_ / 2, canvas_y_ + canvas_h_ / 2); return;
      default: break;
    }
  }
  if (play_mode_) return;  // the document is not edited while playing
  if (ctrl) {
    switch (k) {
      case SDLK_z: shift ? doc_.redo() : doc_.undo(); return;
      case SDLK_y: doc_.redo(); return;
      case SDLK_c: doc_.copy_selection(); return;
      case SDLK_x: doc_.copy_selection(); doc_.delete_selection(); return;
      case SDLK_v: doc_.paste(5.0); return;
      case SDLK_d: doc_.duplicate_selection(5.0); return;
      case SDLK_a: doc_.select_all(); return;
      case SDLK_g: shift ? doc_.ungroup_selection() : doc_.group_selection(); return;
      default: return;
    }
  }
  const double step = shift ? 10.0 : alt ? 0.1 : 1.0;
  switch (k) {
    case SDLK_DELETE:
    case SDLK_BACKSPACE: doc_.delete_selection(); break;
    case SDLK_LEFT: doc_.move_selection(-step, 0); break;
    case SDLK_RIGHT: doc_.move_selection(step, 0); break;
    case SDLK_UP: doc_.move_selection(0, -step); break;
    case SDLK_DOWN: doc_.move_selection(0, step); break;
    case SDLK_PAGEUP: doc_.raise_selection(); break;
    case SDLK_PAGEDOWN: doc_.lower_selection(); break;
    case SDLK_HOME: doc_.bring_selection_to_front(); break;
    case SDLK_END: doc_.send_selection_to_back(); break;
    case SDLK_v: tool_ = Tool::select; break;
    case SDLK_d: tool_ = Tool::dot; break;
    case SDLK_l: tool_ = Tool::line; break;
    case SDLK_r: tool_ = Tool::rect; break;
    case SDLK_e: tool_ = Tool::ellipse; break;
    case SDLK_p: tool_ = Tool::polygon; polygon_points_.clear(); break;
    case SDLK_g: show_grid_ = !show_grid_; break;
    case SDLK_s: snap_ = !snap_; break;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: finish_polygon(); break;
    case SDLK_ESCAPE:
      if (!polygon_points_.empty()) {
        polygon_points_.clear();
      } else if (drag_ == Drag::none) {
        doc_.clear_selection();
      }
      break;
    default: break;
  }
}

void EditorApp::frame() {
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();

  draw_menu_bar();
  if (options_.print_layout) {
    int wx = 0, wy = 0, ww = 0, wh = 0;
    SDL_GetWindowPosition(window_, &wx, &wy);
    SDL_GetWindowSize(window_, &ww, &wh);
    print_layout("window", static_cast<float>(wx), static_cast<float>(wy), static_cast<float>(ww),
                 static_cast<float>(wh));
  }
  const ImGuiIO& io = ImGui::GetIO();
  const float top = ImGui::GetFrameHeight();
  const float W = io.DisplaySize.x;
  const float H = io.DisplaySize.y;
  const float scope_h = play_mode_ ? kScopeHeight : 0.0f;
  const float canvas_w = std::max(50.0f, W - kToolsWidth - kPropertiesWidth);
  const float canvas_h = std::max(50.0f, H - top - kStatusHeight - scope_h);
  draw_tools_panel(0, top, kToolsWidth, H - top - kStatusHeight);
  draw_canvas(kToolsWidth, top, canvas_w, canvas_h);
  if (play_mode_) draw_scope_panel(kToolsWidth, top + canvas_h, canvas_w, scope_h);
  const float props_h = (H - top - kStatusHeight) * 0.62f;
  draw_properties_panel(kToolsWidth + canvas_w, top, kPropertiesWidth, props_h);
  draw_messages_panel(kToolsWidth + canvas_w, top + props_h, kPropertiesWidth, H - top - kStatusHeight - props_h);

  // Status bar
  ImGui::SetNextWindowPos(ImVec2(0, H - kStatusHeight));
  ImGui::SetNextWindowSize(ImVec2(W, kStatusHeight));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  const char* mode = play_mode_ ? "PLAYING" : "DRAWING";
  ImGui::Text("%s | %s%s | zoom %.0f%% (%.2f px/mm) | grid %s, snap %s | %zu elements | %s", mode,
              doc_.dirty() ? "* " : "",
              document_path_.empty() ? "untitled" : std::filesystem::path(document_path_).filename().c_str(),
              view_.zoom() * 100.0, view_.px_per_mm(), show_grid_ ? "on" : "off", snap_ ? "on" : "off",
              doc_.image().children.size(), status_.c_str());
  ImGui::End();

  draw_dialogs();
  any_popup_open_ = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);

  ImGui::Render();
  SDL_SetRenderDrawColor(renderer_, 30, 30, 34, 255);
  SDL_RenderClear(renderer_);
  ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
  SDL_RenderPresent(renderer_);

  if (play_mode_ && play_ && play_->playing()) {
    static std::uint64_t played_change = 0;
    if (played_change != doc_.change_count()) {
      play_->update(doc_.image());
      played_change = doc_.change_count();
    }
  }
  if (options_.benchmark_frames == 0) {
    autosave_if_due();
    refresh_validation();
  }
  update_title();
}

void EditorApp::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New", "Ctrl+N")) request(PendingAction::new_document);
    if (ImGui::MenuItem("Open...", "Ctrl+O")) {
      path_prompt_ = PathPrompt::open;
      path_prompt_opening_ = true;
      path_buffer_[0] = 0;
    }
    if (ImGui::BeginMenu("Open Recent", !recent_.paths().empty())) {
      for (const std::string& p : recent_.paths()) {
        if (ImGui::MenuItem(p.c_str())) request(PendingAction::open_file, p);
      }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save", "Ctrl+S")) save();
    if (ImGui::MenuItem("Save As (.vimg or .png)...", "Ctrl+Shift+S")) {
      path_prompt_ = PathPrompt::save_as;
      path_prompt_opening_ = true;
      std::snprintf(path_buffer_, sizeof path_buffer_, "%s", document_path_.c_str());
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) request(PendingAction::quit);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const bool editing = !play_mode_;
    const bool any = !doc_.selection().empty();
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, editing && doc_.can_undo())) doc_.undo();
    if (ImGui::MenuItem("Redo", "Ctrl+Y", false, editing && doc_.can_redo())) doc_.redo();
    ImGui::Separator();
    if (ImGui::MenuItem("Cut", "Ctrl+X", false, editing && any)) {
      doc_.copy_selection();
      doc_.delete_selection();
    }
    if (ImGui::MenuItem("Copy", "Ctrl+C", false, any)) doc_.copy_selection();
    if (ImGui::MenuItem("Paste", "Ctrl+V", false, editing && doc_.can_paste())) doc_.paste(5.0);
    if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, editing && any)) doc_.duplicate_selection(5.0);
    if (ImGui::MenuItem("Delete", "Del", false, editing && any)) doc_.delete_selection();
    if (ImGui::MenuItem("Select All", "Ctrl+A", false, editing)) doc_.select_all();
    ImGui::Separator();
    if (ImGui::MenuItem("Group", "Ctrl+G", false, editing && any)) doc_.group_selection();
    if (ImGui::MenuItem("Ungroup", "Ctrl+Shift+G", false, editing && any)) doc_.ungroup_selection();
    ImGui::Separator();
    if (ImGui::MenuItem("Bring Forward", "PgUp", false, editing && any)) doc_.raise_selection();
    if (ImGui::MenuItem("Send Backward", "PgDn", false, editing && any)) doc_.lower_selection();
    if (ImGui::MenuItem("Bring to Front", "Home", false, editing && any)) doc_.bring_selection_to_front();
    if (ImGui::MenuItem("Send to Back", "End", false, editing && any)) doc_.send_selection_to_back();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Actual Size", "Ctrl+0")) {
      view_.set_zoom(1.0);
      view_.reset_pan();
    }
    if (ImGui::MenuItem("Zoom In", "Ctrl+=")) view_.zoom_at(1.25, canvas_x_ + canvas_w_ / 2, canvas_y_ + canvas_h_ / 2);
    if (ImGui::MenuItem("Zoom Out", "Ctrl+-")) view_.zoom_at(0.8, canvas_x_ + canvas_w_ / 2, canvas_y_ + canvas_h_ / 2);
    ImGui::MenuItem("Grid", "G", &show_grid_);
    ImGui::MenuItem("Snap to Grid", "S", &snap_);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Mode")) {
    if (ImGui::MenuItem("Drawing", "F5", !play_mode_)) set_play_mode(false);
    if (ImGui::MenuItem("Playing", "F5", play_mode_)) set_play_mode(true);
    if (play_ && ImGui::MenuItem("Record Gesture", nullptr, play_->recording(), play_mode_)) {
      play_->set_recording(!play_->recording());
    }
    if (ImGui::MenuItem("Save Gesture (.csv)...", nullptr, false, play_ && !play_->recorder().empty())) {
      path_prompt_ = PathPrompt::save_gesture;
      path_prompt_opening_ = true;
      std::snprintf(path_buffer_, sizeof path_buffer_, "gesture.csv");
    }
    ImGui::EndMenu();
  }
  ImGui::TextDisabled("| %s%s", doc_.dirty() ? "* " : "",
                      document_path_.empty() ? "untitled" : document_path_.c_str());
  ImGui::EndMainMenuBar();
}

void EditorApp::request(PendingAction action, std::string path) {
  if (doc_.dirty() && action != PendingAction::none) {
    pending_ = action;
    pending_path_ = std::move(path);
    unsaved_prompt_opening_ = true;
    return;
  }
  perform(action, path);
}

void EditorApp::perform(PendingAction action, const std::string& path) {
  pending_ = PendingAction::none;
  switch (action) {
    case PendingAction::new_document:
      if (play_mode_) set_play_mode(false);
      doc_.reset(new_image());
      document_path_.clear();
      load_diagnostics_.clear();
      if (!recovery_prompt_opening_ && !recovery_prompt_active_) recovery_.discard();
      status_ = "new document";
      break;
    case PendingAction::open_file: open_file(path); break;
    case PendingAction::quit: quit_ = true; break;
    case PendingAction::none: break;
  }
}

bool EditorApp::open_file(const std::string& path) {
  LoadResult result = load_image_file(path);
  if (!result.ok()) {
    report_error(result.diagnostics.empty() ? path + ": cannot open" : join_diagnostics(result.diagnostics));
    recent_.remove(path);
    return false;
  }
  if (play_mode_) set_play_mode(false);
  doc_.reset(std::move(*result.image));
  document_path_ = path;
  load_diagnostics_ = result.diagnostics;
  recent_.add(path);
  if (!recovery_prompt_opening_ && !recovery_prompt_active_) recovery_.discard();
  status_ = "opened " + path;
  return true;
}

bool EditorApp::save_to(const std::string& path, bool becomes_document_path) {
  if (auto error = save_image_file(doc_.image(), path)) {
    report_error(*error);
    return false;
  }
  if (becomes_document_path) {
    document_path_ = path;
    doc_.mark_saved();
    recovery_.discard();
  }
  recent_.add(path);
  status_ = "saved " + path;
  return true;
}

void EditorApp::save() {
  if (document_path_.empty()) {
    path_prompt_ = PathPrompt::save_as;
    path_prompt_opening_ = true;
    std::snprintf(path_buffer_, sizeof path_buffer_, "untitled.vimg");
    return;
  }
  save_to(document_path_, true);
}

void EditorApp::set_play_mode(bool on) {
  if (on == play_mode_) return;
  if (on) {
    if (drag_ != Drag::none) {
      doc_.end_gesture();
      drag_ = Drag::none;
    }
    polygon_points_.clear();
    if (!play_) {
      const OutputChoice choice = options_.output;
      play_ = std::make_unique<PlaySession>(
          [choice](std::string& error) { return make_output(choice, error); }, options_.sample_rate_hz);
    }
    if (auto error = play_->start(doc_.image())) {
      report_error("cannot play to " + options_.output.text + ": " + *error);
      return;
    }
    if (!options_.record_gesture.empty()) play_->set_recording(true);
    play_mode_ = true;
    status_ = "playing to " + options_.output.text;
    return;
  }
  play_mode_ = false;
  play_finger_down_ = false;
  if (!play_) return;
  play_->stop();
  status_ = "drawing";
  if (const DriveTap* tap = play_->tap()) {
    std::vector<double> lat = tap->latencies_s();
    if (!lat.empty()) {
      std::sort(lat.begin(), lat.end());
      std::fprintf(stderr, "vimg-editor: %zu drive onsets, event-to-drive latency ms: median %.2f max %.2f\n",
                   lat.size(), lat[lat.size() / 2] * 1e3, lat.back() * 1e3);
    }
  }
  if (!options_.record_gesture.empty() && play_->recording()) {
    if (auto error = play_->recorded_gesture().save(options_.record_gesture)) report_error(*error);
  }
}

void EditorApp::report_error(std::string message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  error_message_ = std::move(message);
  error_opening_ = true;
}

void EditorApp::autosave_if_due() {
  if (recovery_prompt_opening_ || recovery_prompt_active_) return;  // the user decides first
  const double now = monotonic_s();
  if (!doc_.dirty() || doc_.in_gesture()) return;
  if (doc_.change_count() == autosaved_change_ || now - last_autosave_s_ < options_.autosave_interval_s) return;
  if (auto error = recovery_.save(doc_.image(), document_path_)) {
    status_ = "autosave failed: " + *error;
  } else {
    status_ = "autosaved";
  }
  autosaved_change_ = doc_.change_count();
  last_autosave_s_ = now;
}

void EditorApp::offer_recovery() {
  if (recovery_.adopt_orphan()) recovery_prompt_opening_ = true;
}

void EditorApp::update_title() {
  std::string title = std::string(doc_.dirty() ? "*" : "") +
                      (document_path_.empty() ? "untitled" : std::filesystem::path(document_path_).filename().string()) +
                      " - vimg-editor" + (play_mode_ ? " [playing]" : "");
  if (title != last_title_) {
    SDL_SetWindowTitle(window_, title.c_str());
    last_title_ = title;
  }
}

void EditorApp::print_layout(const char* name, float x, float y, float w, float h) {
  if (!options_.print_layout) return;
  char line[256];
  std::snprintf(line, sizeof line, "layout %s %.0f %.0f %.0f %.0f", name, x, y, w, h);
  for (std::string& s : printed_layout_) {
    if (s.rfind(std::string("layout ") + name + " ", 0) == 0) {
      if (s == line) return;
      s = line;
      std::printf("%s\n", line);
      std::fflush(stdout);
      return;
    }
  }
  printed_layout_.emplace_back(line);
  std::printf("%s\n", line);
  std::fflush(stdout);
}

void EditorApp::draw_dialogs() {
  const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
  if (error_opening_) {
    ImGui::OpenPopup("Problem");
    error_opening_ = false;
  }
  if (recovery_prompt_opening_ && !ImGui::IsPopupOpen("Problem")) {
    ImGui::OpenPopup("Recover unsaved work?");
    recovery_prompt_opening_ = false;
    recovery_prompt_active_ = true;
  }
  if (unsaved_prompt_opening_) {
    ImGui::OpenPopup("Unsaved changes");
    unsaved_prompt_opening_ = false;
  }
  if (path_prompt_opening_) {
    ImGui::OpenPopup("File");
    path_prompt_opening_ = false;
    ++path_prompt_count_;
  }

  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Problem", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted(error_message_.c_str());
    if (ImGui::Button("OK", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const std::string origin = recovery_.recorded_origin().string();
    ImGui::Text("vimg-editor did not close normally last time.");
    ImGui::Text("Unsaved work of %s was kept.", origin.empty() ? "an untitled document" : origin.c_str());
    ImGui::Text("Recover it?  (Enter: recover, Esc: discard)");
    print_layout("recover_dialog", ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowWidth(),
                 ImGui::GetWindowHeight());
    const bool recover = ImGui::Button("Recover", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
    ImGui::SameLine();
    const bool discard = ImGui::Button("Discard", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (recover) {
      LoadResult result = load_image_file(recovery_.file());
      if (result.ok()) {
        doc_.reset(std::move(*result.image));
        doc_.mark_unsaved();
        document_path_ = origin;
        status_ = "recovered unsaved work";
      } else {
        error_message_ = join_diagnostics(result.diagnostics);
        error_opening_ = true;
      }
      recovery_prompt_active_ = false;
      ImGui::CloseCurrentPopup();
    } else if (discard) {
      recovery_.discard();
      recovery_prompt_active_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has unsaved changes.", document_path_.empty() ? "This document" : document_path_.c_str());
    ImGui::Text("Save them first?");
    if (ImGui::Button("Save", ImVec2(110, 0))) {
      ImGui::CloseCurrentPopup();
      if (document_path_.empty()) {
        path_prompt_ = PathPrompt::save_as;  // the pending action runs after the save
        path_prompt_opening_ = true;
        std::snprintf(path_buffer_, sizeof path_buffer_, "untitled.vimg");
      } else if (save_to(document_path_, true)) {
        perform(pending_, pending_path_);
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(110, 0))) {
      ImGui::CloseCurrentPopup();
      const PendingAction action = pending_;
      doc_.mark_saved();  // the user chose to lose them
      perform(action, pending_path_);
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      pending_ = PendingAction::none;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }

  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(620, 0));
  if (ImGui::BeginPopupModal("File", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    const char* what = path_prompt_ == PathPrompt::open      ? "Open a .vimg or .png image:"
                       : path_prompt_ == PathPrompt::save_as ? "Save as (.vimg for XML, .png for a picture with the XML inside):"
                                                             : "Save the recorded gesture as CSV:";
    ImGui::TextUnformatted(what);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1);
    const bool entered = ImGui::InputText("##path", path_buffer_, sizeof path_buffer_,
                                          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    if (ImGui::IsItemActive()) {  // ready for typing (scripted tests wait for this)
      const std::string name = "file_prompt" + std::to_string(path_prompt_count_);
      print_layout(name.c_str(), ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                   ImGui::GetItemRectSize().y);
    }
    if (path_prompt_ == PathPrompt::open) {
      ImGui::TextDisabled("Recent files and examples:");
      std::vector<std::string> choices = recent_.paths();
      for (const auto& p : library_) choices.push_back(p.string());
      ImGui::BeginChild("##choices", ImVec2(0, 160), true);
      for (const std::string& c : choices) {
        if (ImGui::Selectable(c.c_str())) std::snprintf(path_buffer_, sizeof path_buffer_, "%s", c.c_str());
      }
      ImGui::EndChild();
    }
    const bool ok = ImGui::Button("OK", ImVec2(120, 0)) || entered;
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (ok && path_buffer_[0] != 0) {
      const std::string path = path_buffer_;
      ImGui::CloseCurrentPopup();
      if (path_prompt_ == PathPrompt::open) {
        request(PendingAction::open_file, path);
      } else if (path_prompt_ == PathPrompt::save_as) {
        if (save_to(path, true) && pending_ != PendingAction::none) perform(pending_, pending_path_);
      } else if (play_) {
        if (auto error = play_->recorded_gesture().save(path)) {
          report_error(*error);
        } else {
          status_ = "gesture saved to " + path;
        }
      }
      path_prompt_ = PathPrompt::none;
    } else if (cancel) {
      pending_ = PendingAction::none;
      path_prompt_ = PathPrompt::none;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

}  // namespace vimg::editor
