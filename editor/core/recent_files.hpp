#pragma once
// The recent-files list: most recent first, no duplicates, at most `capacity` entries, kept in a
// text file (one path a line), written atomically. Reading it is bounded: at most
// kMaxRecentFilesBytes are read, and lines that are not plausible paths (too long, control
// characters, not absolute) are skipped, so a damaged or hostile store never costs more than that.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vimg::editor {

inline constexpr std::size_t kMaxRecentFilesBytes = 256 * 1024;
inline constexpr std::size_t kMaxRecentPathBytes = 4096;  // PATH_MAX on Linux

// The entries of a store's text, most recent first (the parser on its own, for tests and fuzzing).
std::vector<std::string> parse_recent_files(std::string_view text, std::size_t capacity);

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
