// One frame of the editor: the panels laid out around the canvas, the menu bar, the status bar,
// the window title (editor_app.hpp).
#include <imgui.h>
#include <imgui_impl_sdl.h>
#include <imgui_impl_sdlrenderer.h>

#include <algorithm>

#include "editor/editor_app.hpp"
#include "realtime/clock.hpp"

namespace vimg::editor {
namespace {
constexpr float kToolsWidth = 210.0f;
constexpr float kPropertiesWidth = 330.0f;
constexpr float kStatusHeight = 26.0f;
constexpr float kScopeHeight = 150.0f;
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus;
}  // namespace

void EditorApp::set_play_mode(bool on) {
  if (on == playback_.on()) return;
  if (on) canvas_.cancel_interaction();
  playback_.set_on(on, session_.editor().image());
}

void EditorApp::frame() {
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGui::NewFrame();

  draw_menu_bar();
  if (layout_.enabled()) {
    int wx = 0, wy = 0, ww = 0, wh = 0;
    SDL_GetWindowPosition(window_, &wx, &wy);
    SDL_GetWindowSize(window_, &ww, &wh);
    layout_.print("window", static_cast<float>(wx), static_cast<float>(wy), static_cast<float>(ww),
                  static_cast<float>(wh));
  }
  const ImGuiIO& io = ImGui::GetIO();
  const float top = ImGui::GetFrameHeight();
  const float W = io.DisplaySize.x;
  const float H = io.DisplaySize.y;
  const bool playing = playback_.on();
  const float scope_h = playing ? kScopeHeight : 0.0f;
  const float canvas_w = std::max(50.0f, W - kToolsWidth - kPropertiesWidth);
  const float canvas_h = std::max(50.0f, H - top - kStatusHeight - scope_h);

  playback_.update_feel(session_.editor().image(), session_.editor().change_count());
  // Tools panel: play, the drawing tools, the library.
  ImGui::SetNextWindowPos(ImVec2(0, top));
  ImGui::SetNextWindowSize(ImVec2(kToolsWidth, H - top - kStatusHeight));
  ImGui::Begin("Tools", nullptr, kPanelFlags);
  if (playback_.draw_controls()) set_play_mode(!playing);
  ImGui::Separator();
  canvas_.draw_tool_choice(playing);
  ImGui::Separator();
  if (auto path = library_.draw(playing)) request(PendingAction::open_file, *path);
  ImGui::End();
  if (auto images = library_.take_compare_request()) {
    const ActuatorProfile& profile = playback_.feel().profile();
    compare_.start(std::move(*images), {profile.name.empty() ? "ideal" : profile.name, playback_.feel().path().string(),
                                        profile.response});
  }

  if (auto request = compare_.take_proposal_request()) proposal_.start(std::move(request->first), std::move(request->second));

  canvas_.draw(kToolsWidth, top, canvas_w, canvas_h);
  if (playback_.on()) playback_.draw_scope(kToolsWidth, top + canvas_h, canvas_w, scope_h);
  const float props_h = (H - top - kStatusHeight) * 0.62f;
  properties_.draw(kToolsWidth + canvas_w, top, kPropertiesWidth, props_h);
  problems_.draw(kToolsWidth + canvas_w, top + props_h, kPropertiesWidth, H - top - kStatusHeight - props_h,
                 session_.editor(), session_.load_diagnostics(), layout_);
  if (auditioned_) {
    // While a change is auditioned the canvas is free to rub: the comparison hides, the proposal
    // shrinks to one line at the canvas's foot.
    proposal_.draw(kToolsWidth + 20.0f, top + canvas_h - 90.0f, std::min(560.0f, canvas_w - 40.0f), 0.0f, session_.path());
  } else {
    compare_.draw(kToolsWidth + 20.0f, top + 20.0f, std::min(640.0f, canvas_w - 40.0f), std::min(420.0f, canvas_h - 40.0f));
    proposal_.draw(kToolsWidth + 30.0f, top + 30.0f, std::min(680.0f, canvas_w - 40.0f),
                   std::min(520.0f, canvas_h - 40.0f), session_.path());
  }
  if (auto action = proposal_.take_action()) handle_proposal_action(*action);
  audition_.draw(kToolsWidth + 40.0f, top + 40.0f);
  draw_status_bar(W, H);

  draw_dialogs();
  any_popup_open_ = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);

  ImGui::Render();
  SDL_SetRenderDrawColor(renderer_, 30, 30, 34, 255);
  SDL_RenderClear(renderer_);
  ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
  SDL_RenderPresent(renderer_);

  const DocumentEditor& doc = session_.editor();
  follow_document_or_audition();
  playback_.show_device_messages();
  if (options_.benchmark_frames == 0) {
    const double now = monotonic_s();
    if (auto status = session_.autosave_if_due(now)) notices_.status = *status;
    problems_.refresh(doc, session_.path().empty() ? "untitled.vimg" : session_.path(), now);
  }
  update_title();
}

void EditorApp::draw_status_bar(float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(0, h - kStatusHeight));
  ImGui::SetNextWindowSize(ImVec2(w, kStatusHeight));
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  const Viewport& view = canvas_.view();
  ImGui::Text("%s | %s%s | zoom %.0f%% (%.2f px/mm) | grid %s, snap %s | %zu elements | %s",
              playback_.on() ? "PLAYING" : "DRAWING", session_.editor().dirty() ? "* " : "",
              session_.display_name().c_str(), view.zoom() * 100.0, view.px_per_mm(),
              canvas_.show_grid() ? "on" : "off", canvas_.snap() ? "on" : "off",
              session_.editor().image().children.size(), notices_.status.c_str());
  ImGui::End();
}

void EditorApp::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  DocumentEditor& doc = session_.editor();
  const bool file_menu = ImGui::BeginMenu("File");
  layout_.print("menu_file", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  if (file_menu) {
    if (ImGui::MenuItem("New", "Ctrl+N")) request(PendingAction::new_document);
    if (ImGui::MenuItem("Open...", "Ctrl+O")) prompt_path(PathPrompt::open, "");
    if (ImGui::MenuItem("Import (.svg or .png)...")) prompt_path(PathPrompt::import_file, "");
    layout_.print("menu_import", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                  ImGui::GetItemRectSize().y);
    if (ImGui::BeginMenu("Open Recent", !session_.recent().paths().empty())) {
      for (const std::string& p : session_.recent().paths()) {
        if (ImGui::MenuItem(p.c_str())) request(PendingAction::open_file, p);
      }
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save", "Ctrl+S")) save();
    if (ImGui::MenuItem("Save As (.vimg or .png)...", "Ctrl+Shift+S")) prompt_path(PathPrompt::save_as, session_.path());
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) request(PendingAction::quit);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    const bool editing = !playback_.on();
    const bool any = !doc.selection().empty();
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, editing && doc.can_undo())) doc.undo();
    if (ImGui::MenuItem("Redo", "Ctrl+Y", false, editing && doc.can_redo())) doc.redo();
    ImGui::Separator();
    if (ImGui::MenuItem("Cut", "Ctrl+X", false, editing && any)) {
      doc.copy_selection();
      doc.delete_selection();
    }
    if (ImGui::MenuItem("Copy", "Ctrl+C", false, any)) doc.copy_selection();
    if (ImGui::MenuItem("Paste", "Ctrl+V", false, editing && doc.can_paste())) doc.paste(5.0);
    if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, editing && any)) doc.duplicate_selection(5.0);
    if (ImGui::MenuItem("Delete", "Del", false, editing && any)) doc.delete_selection();
    if (ImGui::MenuItem("Select All", "Ctrl+A", false, editing)) doc.select_all();
    ImGui::Separator();
    if (ImGui::MenuItem("Group", "Ctrl+G", false, editing && any)) doc.group_selection();
    if (ImGui::MenuItem("Ungroup", "Ctrl+Shift+G", false, editing && any)) doc.ungroup_selection();
    ImGui::Separator();
    if (ImGui::MenuItem("Bring Forward", "PgUp", false, editing && any)) doc.raise_selection();
    if (ImGui::MenuItem("Send Backward", "PgDn", false, editing && any)) doc.lower_selection();
    if (ImGui::MenuItem("Bring to Front", "Home", false, editing && any)) doc.bring_selection_to_front();
    if (ImGui::MenuItem("Send to Back", "End", false, editing && any)) doc.send_selection_to_back();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Actual Size", "Ctrl+0")) canvas_.actual_size();
    if (ImGui::MenuItem("Zoom In", "Ctrl+=")) canvas_.zoom_by(1.25);
    if (ImGui::MenuItem("Zoom Out", "Ctrl+-")) canvas_.zoom_by(0.8);
    ImGui::MenuItem("Grid", "G", &canvas_.show_grid());
    ImGui::MenuItem("Snap to Grid", "S", &canvas_.snap());
    ImGui::EndMenu();
  }
  const bool mode_menu = ImGui::BeginMenu("Mode");
  layout_.print("menu_mode", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  if (mode_menu) {
    const bool playing = playback_.on();
    if (ImGui::MenuItem("Drawing", "F5", !playing)) set_play_mode(false);
    if (ImGui::MenuItem("Playing", "F5", playing)) set_play_mode(true);
    if (playback_.has_session() && ImGui::MenuItem("Record Gesture", nullptr, playback_.recording(), playing)) {
      playback_.toggle_recording();
    }
    if (ImGui::MenuItem("Save Gesture (.csv)...", nullptr, false, playback_.can_save_gesture())) {
      prompt_path(PathPrompt::save_gesture, "gesture.csv");
    }
    ImGui::Separator();
    // Touch-latency compensation (docs/latency.md): from the next start of playing mode.
    TouchCompensation& touch = playback_.touch();
    if (ImGui::MenuItem("Touch Prediction", nullptr, &touch.enabled)) save_touch_settings();
    layout_.print("menu_touch_prediction", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                  ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
    float latency_ms = static_cast<float>(touch.panel_latency_s * 1e3);
    if (ImGui::SliderFloat("Touch latency (ms)", &latency_ms, 0.0f, static_cast<float>(kMaxTouchPanelLatency_s * 1e3), "%.1f")) {
      touch.panel_latency_s = std::clamp(static_cast<double>(latency_ms), 0.0, kMaxTouchPanelLatency_s * 1e3) * 1e-3;
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) save_touch_settings();  // once the slider is let go
    ImGui::Separator();
    const bool audition = ImGui::MenuItem("Audition on a device", nullptr, audition_.serving());
    layout_.print("menu_audition", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                  ImGui::GetItemRectSize().y);
    if (audition) {
      if (session_.path().empty()) {
        notices_.report_error("Audition on a device plays the saved file: save the image first (Ctrl+S).");
      } else {
        audition_.start(session_.path(), playback_.feel().path().string());
      }
    }
    ImGui::EndMenu();
  }
  ImGui::TextDisabled("| %s%s", doc.dirty() ? "* " : "", session_.path().empty() ? "untitled" : session_.path().c_str());
  ImGui::EndMainMenuBar();
}

void EditorApp::update_title() {
  const std::string title = std::string(session_.editor().dirty() ? "*" : "") + session_.display_name() +
                            " - vimg-editor" + (playback_.on() ? " [playing]" : "");
  if (title != last_title_) {
    SDL_SetWindowTitle(window_, title.c_str());
    last_title_ = title;
  }
}

}  // namespace vimg::editor
