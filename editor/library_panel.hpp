#pragma once
// The library: the bundled examples and the designer's own folder (--library-dir, else
// ~/vibroimages), listed in the tools panel; an entry is dragged onto the canvas to place it
// (canvas_view.hpp kLibraryPayload) or double-clicked to open it. A click selects an entry,
// Ctrl+click adds or removes one; "Predict confusion" asks for the selected images to be compared
// (compare_window.hpp). GUI thread.
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace vimg::editor {

class LayoutLog;

class LibraryPanel {
 public:
  LibraryPanel(std::string library_dir, LayoutLog& layout);
  void refresh();
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // Draws the list; returns the file double-clicked to be opened, if any. `playing`: no dragging.
  std::optional<std::string> draw(bool playing);
  // The selected images, in the list's order, when "Predict confusion" was pressed since the last
  // call.
  std::optional<std::vector<std::filesystem::path>> take_compare_request();

 private:
  std::string library_dir_;
  LayoutLog& layout_;
  std::vector<std::filesystem::path> files_;
  std::set<std::filesystem::path> selected_;
  bool compare_requested_ = false;
};

}  // namespace vimg::editor
