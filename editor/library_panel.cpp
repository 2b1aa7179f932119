#include "editor/library_panel.hpp"

#include "storage/shipped_data.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>

#include "editor/canvas_view.hpp"
#include "editor/core/layout_log.hpp"

namespace vimg::editor {

LibraryPanel::LibraryPanel(std::string library_dir, LayoutLog& layout)
    : library_dir_(std::move(library_dir)), layout_(layout) {}

void LibraryPanel::refresh() {
  files_.clear();
  std::vector<std::filesystem::path> dirs;
  if (const auto data = shipped_data_dir()) dirs.push_back(*data / "examples");
  if (!library_dir_.empty()) {
    dirs.emplace_back(library_dir_);
  } else if (const char* home = std::getenv("HOME"); home && *home) {
    dirs.push_back(std::filesystem::path(home) / "vibroimages");
  }
  for (const auto& dir : dirs) {
    std::error_code ec;
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const auto ext = entry.path().extension();
      if (entry.is_regular_file() && (ext == ".vimg" || ext == ".png")) found.push_back(entry.path());
    }
    std::sort(found.begin(), found.end());
    files_.insert(files_.end(), found.begin(), found.end());
  }
  std::erase_if(selected_, [&](const auto& p) { return std::find(files_.begin(), files_.end(), p) == files_.end(); });
}

std::optional<std::vector<std::filesystem::path>> LibraryPanel::take_compare_request() {
  if (!compare_requested_) return std::nullopt;
  compare_requested_ = false;
  std::vector<std::filesystem::path> chosen;
  for (const auto& path : files_) {
    if (selected_.count(path)) chosen.push_back(path);
  }
  if (chosen.size() < 2) return std::nullopt;
  return chosen;
}

std::optional<std::string> LibraryPanel::draw(bool playing) {
  std::optional<std::string> open;
  ImGui::Text("Library");
  ImGui::SameLine();
  if (ImGui::SmallButton("Refresh")) refresh();
  ImGui::TextDisabled("drag an image onto the canvas");
  ImGui::TextDisabled("Ctrl+click several to compare");
  const std::string compare = "Predict confusion (" + std::to_string(selected_.size()) + ")";
  ImGui::BeginDisabled(selected_.size() < 2);
  if (ImGui::SmallButton(compare.c_str())) compare_requested_ = true;
  ImGui::EndDisabled();
  layout_.print("compare_button", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                ImGui::GetItemRectSize().y);
  // The selection, for scripts to wait on: a line each time the count changes.
  layout_.print("compare_selection_" + std::to_string(selected_.size()), 0.0f, 0.0f, 0.0f, 0.0f);
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Which of the selected images will people confuse? (as vimg compare predicts it)");
  ImGui::BeginChild("##library", ImVec2(0, 0), true);
  layout_.print("library_list", ImGui::GetWindowPos().x, ImGui::GetWindowPos().y, ImGui::GetWindowSize().x,
                ImGui::GetWindowSize().y);
  for (const auto& path : files_) {
    const std::string name = path.parent_path().filename().string() + "/" + path.filename().string();
    if (ImGui::Selectable(name.c_str(), selected_.count(path) > 0)) {
      if (ImGui::GetIO().KeyCtrl) {
        if (!selected_.erase(path)) selected_.insert(path);
      } else {
        selected_ = {path};
      }
    }
    layout_.print("library_" + name, ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                  ImGui::GetItemRectSize().y);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(0)) open = path.string();
    if (!playing && ImGui::BeginDragDropSource()) {
      const std::string p = path.string();
      ImGui::SetDragDropPayload(kLibraryPayload, p.data(), p.size());
      ImGui::Text("place %s", name.c_str());
      ImGui::EndDragDropSource();
    }
  }
  ImGui::EndChild();
  return open;
}

}  // namespace vimg::editor
