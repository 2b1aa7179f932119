#pragma once
// The file chooser of Open, Import, Save As and Save Gesture: a folder's listing (folders first, then the
// files the chosen filter accepts), Up and into folders, recent folders and recent files, and a
// name field that also takes a typed path (relative to the folder shown, ~ for home, or
// absolute). The listing logic is editor/core/folder_listing.*; the recent folders are kept in
// the config folder (a RecentFiles list, written atomically). GUI thread.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "editor/core/folder_listing.hpp"
#include "editor/core/recent_files.hpp"

namespace vimg::editor {

class LayoutLog;

class FileChooser {
 public:
  enum class Purpose { open, import_file, save_as, save_gesture };
  FileChooser(LayoutLog& layout, std::filesystem::path recent_folders_store);

  // Opens the chooser on the next draw(): in the folder of `initial` if it names one (else the
  // most recent folder, else the working folder), with its file name in the name field.
  // `recent_files` are offered too (Open).
  void open(Purpose purpose, const std::string& initial, std::vector<std::string> recent_files = {});
  bool is_open() const { return open_; }
  Purpose purpose() const { return purpose_; }

  struct Result {
    bool chosen = false;  // false: cancelled
    std::string path;
  };
  // Draws the modal; returns what the designer decided, once.
  std::optional<Result> draw();
  const std::vector<std::string>& recent_folders() const { return recent_folders_.paths(); }

 private:
  void go_to(const std::filesystem::path& folder);
  void relist();
  void draw_places();
  bool draw_listing();  // true: a file was double-clicked
  std::optional<Result> accept_name();

  LayoutLog& layout_;
  RecentFiles recent_folders_;
  bool open_ = false;
  bool opening_ = false;
  int count_ = 0;  // how often it opened (scripts wait for "file_promptN")
  Purpose purpose_ = Purpose::open;
  std::vector<FileFilter> filters_;
  int filter_ = 0;
  std::filesystem::path folder_;
  FolderListing listing_;
  std::vector<std::string> recent_files_;
  char name_[1024] = {};
  std::string message_;
};

}  // namespace vimg::editor
