#pragma once
// The library: the bundled examples and the designer's own folder (--library-dir, else
// ~/vibroimages), listed in the tools panel; an entry is dragged onto the canvas to place it
// (canvas_view.hpp kLibraryPayload) or double-clicked to open it. GUI thread.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vimg::editor {

class LibraryPanel {
 public:
  explicit LibraryPanel(std::string library_dir);
  void refresh();
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // Draws the list; returns the file double-clicked to be opened, if any. `playing`: no dragging.
  std::optional<std::string> draw(bool playing);

 private:
  std::string library_dir_;
  std::vector<std::filesystem::path> files_;
};

}  // namespace vimg::editor
