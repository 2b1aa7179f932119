#pragma once
// The recent-files list: most recent first, no duplicates, at most `capacity` entries, kept in a
// store file (storage/recent_files_file.hpp: one path a line, written atomically, read bounded).
#include <filesystem>
#include <string>
#include <vector>

#include "storage/recent_files_file.hpp"

namespace vimg::editor {

class RecentFiles {
 public:
  RecentFiles(std::filesystem::path store, std::size_t capacity = 10);

  const std::vector<std::string>& paths() const { return paths_; }
  void add(const std::string& path);  // moves it to the front and writes the store
  void remove(const std::string& path);

 private:
  void write() const;
  std::filesystem::path store_;
  std::size_t capacity_;
  std::vector<std::string> paths_;
};

}  // namespace vimg::editor
