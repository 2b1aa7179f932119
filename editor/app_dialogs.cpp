// The dialogs (problem, recovery, unsaved changes, file) and the file actions they lead to
// (editor_app.hpp).
#include <imgui.h>

#include <cstdio>

#include "editor/editor_app.hpp"
#include "storage/limits.hpp"

namespace vimg::editor {

void EditorApp::request(PendingAction action, std::string path) {
  if (session_.editor().dirty() && action != PendingAction::none) {
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
      set_play_mode(false);
      session_.new_document();
      notices_.status = "new document";
      break;
    case PendingAction::open_file: open_file(path); break;
    case PendingAction::import_file: import_file(path); break;
    case PendingAction::quit: quit_ = true; break;
    case PendingAction::none: break;
  }
}

bool EditorApp::open_file(const std::string& path) {
  if (auto error = session_.open(path, [this] { set_play_mode(false); })) {
    notices_.report_error(*error);
    return false;
  }
  notices_.status = "opened " + path;
  return true;
}

bool EditorApp::import_file(const std::string& path) {
  if (auto error = session_.import_into_new_document(path, import_options_, [this] { set_play_mode(false); })) {
    notices_.report_error(*error);
    return false;
  }
  const std::size_t warnings = session_.load_diagnostics().size();
  notices_.status = session_.path().empty() ? "imported " + path + (warnings ? " (" + std::to_string(warnings) + " warnings: see Problems)" : "")
                                            : "opened " + path;
  return true;
}

bool EditorApp::save_to(const std::string& path, bool becomes_document_path) {
  if (auto error = session_.save_to(path, becomes_document_path)) {
    notices_.report_error(*error);
    return false;
  }
  notices_.status = "saved " + path;
  return true;
}

void EditorApp::save() {
  if (session_.path().empty()) {
    prompt_path(PathPrompt::save_as, "untitled.vimg");
    return;
  }
  save_to(session_.path(), true);
}

void EditorApp::prompt_path(PathPrompt what, const std::string& initial) {
  path_prompt_ = what;
  const FileChooser::Purpose purpose = what == PathPrompt::open          ? FileChooser::Purpose::open
                                       : what == PathPrompt::import_file ? FileChooser::Purpose::import_file
                                       : what == PathPrompt::save_as     ? FileChooser::Purpose::save_as
                                                                         : FileChooser::Purpose::save_gesture;
  chooser_.open(purpose, initial, what == PathPrompt::open ? session_.recent().paths() : std::vector<std::string>{});
}

void EditorApp::draw_dialogs() {
  if (notices_.error_opening) {
    ImGui::OpenPopup("Problem");
    notices_.error_opening = false;
  }
  if (recovery_prompt_opening_ && !ImGui::IsPopupOpen("Problem")) {
    ImGui::OpenPopup("Recover unsaved work?");
    recovery_prompt_opening_ = false;
  }
  if (unsaved_prompt_opening_) {
    ImGui::OpenPopup("Unsaved changes");
    unsaved_prompt_opening_ = false;
  }
  const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Problem", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::TextUnformatted(notices_.error_message.c_str());
    if (ImGui::Button("OK", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
  draw_recovery_dialog();
  draw_unsaved_dialog();
  draw_path_dialog();
  draw_import_dialog();
}

void EditorApp::draw_recovery_dialog() {
  const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const std::string origin = session_.recovery_origin().string();
  ImGui::Text("vimg-editor did not close normally last time.");
  ImGui::Text("Unsaved work of %s was kept.", origin.empty() ? "an untitled document" : origin.c_str());
  ImGui::Text("Recover it?  (Enter: recover, Esc: discard)");
  layout_.print("recover_dialog", ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowWidth(),
                ImGui::GetWindowHeight());
  const bool recover = ImGui::Button("Recover", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
  ImGui::SameLine();
  const bool discard = ImGui::Button("Discard", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  if (recover) {
    if (auto error = session_.recover()) {
      notices_.error_message = *error;
      notices_.error_opening = true;
    } else {
      notices_.status = "recovered unsaved work";
    }
    ImGui::CloseCurrentPopup();
  } else if (discard) {
    session_.discard_recovery();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void EditorApp::draw_unsaved_dialog() {
  const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("%s has unsaved changes.", session_.path().empty() ? "This document" : session_.path().c_str());
  ImGui::Text("Save them first?");
  if (ImGui::Button("Save", ImVec2(110, 0))) {
    ImGui::CloseCurrentPopup();
    if (session_.path().empty()) {
      prompt_path(PathPrompt::save_as, "untitled.vimg");  // the pending action runs after the save
    } else if (save_to(session_.path(), true)) {
      perform(pending_, pending_path_);
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard", ImVec2(110, 0))) {
    ImGui::CloseCurrentPopup();
    const PendingAction action = pending_;
    session_.editor().mark_saved();  // the user chose to lose them
    perform(action, pending_path_);
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    pending_ = PendingAction::none;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void EditorApp::path_chosen(const std::string& path) {
  if (path_prompt_ == PathPrompt::open) {
    request(PendingAction::open_file, path);
  } else if (path_prompt_ == PathPrompt::import_file) {
    import_chosen(path);
  } else if (path_prompt_ == PathPrompt::save_as) {
    if (save_to(path, true) && pending_ != PendingAction::none) perform(pending_, pending_path_);
  } else if (auto error = playback_.save_gesture(path)) {
    notices_.report_error(*error);
  } else {
    notices_.status = "gesture saved to " + path;
  }
  path_prompt_ = PathPrompt::none;
}

void EditorApp::draw_path_dialog() {
  const auto result = chooser_.draw();
  if (!result) return;
  if (result->chosen) {
    path_chosen(result->path);
  } else {
    pending_ = PendingAction::none;
    path_prompt_ = PathPrompt::none;
  }
}

void EditorApp::import_chosen(const std::string& path) {
  const ImportQuestion q = import_question(path);
  if (q.picture && q.vibroimage) {  // a PNG vibroimage is simply opened
    request(PendingAction::open_file, path);
    return;
  }
  import_path_ = path;
  import_picture_ = q.picture;
  import_width_mm_ = q.width_mm;
  import_levels_ = 4;
  import_set_mm_per_unit_ = false;
  import_mm_per_unit_ = 1.0;
  import_prompt_opening_ = true;
}

void EditorApp::draw_import_dialog() {
  if (import_prompt_opening_ && !ImGui::IsPopupOpen("File")) {
    ImGui::OpenPopup("Import");
    import_prompt_opening_ = false;
  }
  const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
  ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal("Import", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("Import %s", import_path_.c_str());
  if (import_picture_) {
    ImGui::SetNextItemWidth(160);
    ImGui::InputDouble("width (mm)", &import_width_mm_, 1.0, 10.0, "%.1f");
    ImGui::SetNextItemWidth(160);
    ImGui::SliderInt("grey levels", &import_levels_, 1, kMaxPictureLevels);
  } else {
    ImGui::Checkbox("mm per SVG unit (else from the file's size)", &import_set_mm_per_unit_);
    if (import_set_mm_per_unit_) {
      ImGui::SetNextItemWidth(160);
      ImGui::InputDouble("mm per unit", &import_mm_per_unit_, 0.01, 0.1, "%.4f");
    }
  }
  ImGui::TextDisabled("Enter: import, Esc: cancel");
  layout_.print("import_dialog", ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowWidth(),
                ImGui::GetWindowHeight());
  // Not the Enter that chose the file in the chooser (the popup opens in the frame of that press).
  const bool keys = !ImGui::IsWindowAppearing();
  const bool ok = ImGui::Button("Import", ImVec2(120, 0)) || (keys && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)));
  ImGui::SameLine();
  const bool cancel =
      ImGui::Button("Cancel", ImVec2(120, 0)) || (keys && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)));
  if (ok) {
    ImGui::CloseCurrentPopup();
    import_options_ = ImportOptions{};
    if (import_picture_) {
      import_options_.width_mm = import_width_mm_;
      import_options_.levels = import_levels_;
    } else if (import_set_mm_per_unit_) {
      import_options_.mm_per_unit = import_mm_per_unit_;
    }
    request(PendingAction::import_file, import_path_);  // asks to save unsaved changes first
  } else if (cancel) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace vimg::editor
