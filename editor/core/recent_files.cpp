#include "editor/core/recent_files.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

#include "storage/atomic_file.hpp"

namespace vimg::editor {

std::vector<std::string> parse_recent_files(std::string_view text, std::size_t capacity) {
  std::vector<std::string> paths;
  while (!text.empty() && paths.size() < capacity) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    const bool plausible = !line.empty() && line.size() <= kMaxRecentPathBytes && line.front() == '/' &&
                           std::none_of(line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
    if (plausible && std::find(paths.begin(), paths.end(), line) == paths.end()) paths.emplace_back(line);
  }
  return paths;
}

RecentFiles::RecentFiles(std::filesystem::path store, std::size_t capacity)
    : store_(std::move(store)), capacity_(capacity) {
  std::ifstream in(store_, std::ios::binary);
  std::string text(kMaxRecentFilesBytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  paths_ = parse_recent_files(text, capacity_);
}

void RecentFiles::add(const std::string& path) {
  std::error_code ec;
  std::filesystem::path abs = std::filesystem::absolute(path, ec);
  const std::string key = ec ? path : abs.lexically_normal().string();
  paths_.erase(std::remove(paths_.begin(), paths_.end(), key), paths_.end());
  paths_.insert(paths_.begin(), key);
  if (paths_.size() > capacity_) paths_.resize(capacity_);
  write();
}

void RecentFiles::remove(const std::string& path) {
  paths_.erase(std::remove(paths_.begin(), paths_.end(), path), paths_.end());
  write();
}

void RecentFiles::write() const {
  std::error_code ec;
  std::filesystem::create_directories(store_.parent_path(), ec);
  std::string text;
  for (const std::string& p : paths_) text += p + '\n';
  write_file_atomically(store_, text);  // the list is a convenience: a failed write is not worth a dialog
}

}  // namespace vimg::editor
