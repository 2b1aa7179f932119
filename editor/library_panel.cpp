#include "editor/library_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>

#include "editor/canvas_view.hpp"

namespace vimg::editor {

LibraryPanel::LibraryPanel(std::string library_dir) : library_dir_(std::move(library_dir)) {}

void LibraryPanel::refresh() {
  files_.clear();
  std::vector<std::filesystem::path> dirs{VIMG_EXAMPLES_DIR};
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
}

std::optional<std::string> LibraryPanel::draw(bool playing) {
  std::optional<std::string> open;
  ImGui::Text("Library");
  ImGui::SameLine();
  if (ImGui::SmallButton("Refresh")) refresh();
  ImGui::TextDisabled("drag an image onto the canvas");
  ImGui::BeginChild("##library", ImVec2(0, 0), true);
  for (const auto& path : files_) {
    const std::string name = path.parent_path().filename().string() + "/" + path.filename().string();
    ImGui::Selectable(name.c_str());
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
