// The window, the event loop and the keyboard shortcuts (editor_app.hpp).
#include "editor/editor_app.hpp"

#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include "realtime/clock.hpp"
#include "storage/print_diagnostics.hpp"
#include "storage/touch_settings_file.hpp"

namespace vimg::editor {
namespace {

constexpr double kFramePeriodS = 1.0 / 60.0;
// Idle: after this many frames without input (ImGui settles hover and popup state in a frame or
// two) the editor stops drawing until an event arrives, waking at kIdleWakeMs for autosave and
// status. Playing mode draws continuously (the oscilloscope and the finger trail move).
constexpr int kSettleFrames = 3;
constexpr int kIdleWakeMs = 250;

std::filesystem::path config_dir() {
  if (const char* c = std::getenv("XDG_CONFIG_HOME"); c && *c) return std::filesystem::path(c) / "vimg-editor";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".config" / "vimg-editor";
  return std::filesystem::temp_directory_path() / "vimg-editor";
}

DocumentSession::Options session_options(const EditorOptions& options) {
  DocumentSession::Options o;
  o.recent_store = config_dir() / "recent.txt";
  o.recovery_dir = options.recovery_dir.empty() ? RecoveryStore::default_dir() : std::filesystem::path(options.recovery_dir);
  o.autosave_interval_s = options.autosave_interval_s;
  o.tool_version = VIMG_VERSION;
  return o;
}

}  // namespace

EditorApp::EditorApp(EditorOptions options)
    : options_(std::move(options)),
      layout_(options_.print_layout),
      session_(session_options(options_)),
      playback_(options_, notices_, layout_, config_dir() / "recent-folders.txt"),
      canvas_(session_.editor(), playback_, notices_, layout_),
      properties_(session_.editor(), notices_, layout_),
      library_(options_.library_dir, layout_),
      compare_(layout_),
      proposal_(layout_),
      chooser_(layout_, config_dir() / "recent-folders.txt") {
  properties_.set_feel(&playback_.feel());
  touch_settings_path_ = config_dir() / "touch-latency.txt";
  load_touch_settings();
}

void EditorApp::load_touch_settings() {
  const TouchSettingsRead read = read_touch_settings(touch_settings_path_);
  print_diagnostics(read.diagnostics);
  TouchCompensation& touch = playback_.touch();
  if (read.settings.latency_ms && !options_.touch_latency_given) touch.panel_latency_s = *read.settings.latency_ms * 1e-3;
  if (read.settings.prediction && !options_.touch_prediction_given) touch.enabled = *read.settings.prediction;
}

void EditorApp::save_touch_settings() {
  const TouchCompensation& touch = playback_.touch();
  if (const auto error = write_touch_settings(touch_settings_path_, touch.panel_latency_s * 1e3, touch.enabled, "vimg-editor")) {
    notices_.report_error("The touch latency setting was not kept: " + *error);
  }
}

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
  canvas_.set_density(px_per_mm, options_.zoom);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; nothing to remember
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0.0f;
  ImGui_ImplSDL2_InitForSDLRenderer(window_);
  ImGui_ImplSDLRenderer_Init(renderer_);
  canvas_.set_renderer(renderer_);
  return true;
}

void EditorApp::shutdown_window() {
  playback_.set_on(false, session_.editor().image());
  canvas_.set_renderer(nullptr);  // its texture goes before the renderer
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
  // First: opening the file must not drop the work of a crashed session.
  if (session_.offer_recovery()) recovery_prompt_opening_ = true;
  if (!options_.file.empty()) open_file(options_.file);
  library_.refresh();
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
    buttons_changed_this_frame_.clear();
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
    if (!playback_.on() && frames_since_input_ > kSettleFrames && held_events_.empty()) {
      // Nothing moves: sleep until the user does something, waking only to autosave. A frame is
      // drawn again for an event or for a new status line (e.g. "autosaved").
      SDL_Event e;
      bool event = false;
      while (!quit_ && !(event = SDL_WaitEventTimeout(&e, kIdleWakeMs) != 0)) {
        if (auto status = session_.autosave_if_due(monotonic_s())) {
          notices_.status = *status;
          break;
        }
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
  if (playback_.on()) set_play_mode(false);
  if (!frame_times_s.empty()) {
    print_benchmark(frame_times_s);
  } else {
    session_.end_session();  // a clean exit: the user has chosen what to keep
  }
  return 0;
}

void EditorApp::print_benchmark(std::vector<double>& frame_times_s) const {
  std::sort(frame_times_s.begin(), frame_times_s.end());
  const double mean =
      std::accumulate(frame_times_s.begin(), frame_times_s.end(), 0.0) / static_cast<double>(frame_times_s.size());
  const auto pct = [&](double p) {
    return frame_times_s[std::min(frame_times_s.size() - 1,
                                  static_cast<std::size_t>(p * static_cast<double>(frame_times_s.size())))];
  };
  SDL_RendererInfo info{};
  SDL_GetRendererInfo(renderer_, &info);
  std::printf(
      "benchmark: renderer=%s primitives=%zu frames=%zu frame_ms mean=%.2f p50=%.2f p99=%.2f max=%.2f fps=%.1f "
      "canvas_builds=%llu\n",
      info.name ? info.name : "?", session_.editor().image().children.size(), frame_times_s.size(), mean * 1e3,
      pct(0.5) * 1e3, pct(0.99) * 1e3, frame_times_s.back() * 1e3, 1.0 / mean,
      static_cast<unsigned long long>(canvas_.cache_builds()));
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
  // Mouse buttons likewise: one change of a button per frame, so a quick double-click is seen as
  // down, up, down (the later changes wait for the frames after).
  if (event.type == SDL_MOUSEBUTTONDOWN || event.type == SDL_MOUSEBUTTONUP) {
    const Uint8 button = event.button.button;
    if (std::find(buttons_changed_this_frame_.begin(), buttons_changed_this_frame_.end(), button) !=
        buttons_changed_this_frame_.end()) {
      held_events_.push_back(event);
      return;
    }
    buttons_changed_this_frame_.push_back(button);
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
  playback_.handle_input(event, canvas_, window_, any_popup_open_);
  switch (event.type) {
    case SDL_QUIT: request(PendingAction::quit); break;
    case SDL_WINDOWEVENT:
      if (event.window.event == SDL_WINDOWEVENT_CLOSE) request(PendingAction::quit);
      break;
    case SDL_KEYDOWN:
      if (!ImGui::GetIO().WantTextInput) handle_shortcut(event.key);
      break;
    case SDL_RENDER_TARGETS_RESET:
    case SDL_RENDER_DEVICE_RESET: canvas_.picture_lost(); break;
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
    set_play_mode(!playback_.on());
    return;
  }
  if (ctrl) {
    switch (k) {
      case SDLK_n: request(PendingAction::new_document); return;
      case SDLK_o: prompt_path(PathPrompt::open, ""); return;
      case SDLK_s:
        if (shift || session_.path().empty()) {
          prompt_path(PathPrompt::save_as, session_.path());
        } else {
          save();
        }
        return;
      case SDLK_q: request(PendingAction::quit); return;
      case SDLK_0: canvas_.actual_size(); return;
      case SDLK_EQUALS:
      case SDLK_PLUS: canvas_.zoom_by(1.25); return;
      case SDLK_MINUS: canvas_.zoom_by(0.8); return;
      default: break;
    }
  }
  if (playback_.on()) return;  // the document is not edited while playing
  DocumentEditor& doc = session_.editor();
  if (ctrl) {
    switch (k) {
      case SDLK_z: shift ? doc.redo() : doc.undo(); return;
      case SDLK_y: doc.redo(); return;
      case SDLK_c: doc.copy_selection(); return;
      case SDLK_x: doc.copy_selection(); doc.delete_selection(); return;
      case SDLK_v: doc.paste(5.0); return;
      case SDLK_d: doc.duplicate_selection(5.0); return;
      case SDLK_a: doc.select_all(); return;
      case SDLK_g: shift ? doc.ungroup_selection() : doc.group_selection(); return;
      default: return;
    }
  }
  const double step = shift ? 10.0 : alt ? 0.1 : 1.0;
  switch (k) {
    case SDLK_DELETE:
    case SDLK_BACKSPACE:
      if (!canvas_.delete_chosen_vertex()) doc.delete_selection();
      break;
    case SDLK_LEFT: doc.move_selection(-step, 0); break;
    case SDLK_RIGHT: doc.move_selection(step, 0); break;
    case SDLK_UP: doc.move_selection(0, -step); break;
    case SDLK_DOWN: doc.move_selection(0, step); break;
    case SDLK_PAGEUP: doc.raise_selection(); break;
    case SDLK_PAGEDOWN: doc.lower_selection(); break;
    case SDLK_HOME: doc.bring_selection_to_front(); break;
    case SDLK_END: doc.send_selection_to_back(); break;
    default: canvas_.handle_key(k); break;
  }
}

}  // namespace vimg::editor
