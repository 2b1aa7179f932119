#include "editor/core/recent_files.hpp"

#include <algorithm>
#include <system_error>

namespace vimg::editor {

RecentFiles::RecentFiles(std::filesystem::path store, std::size_t capacity)
    : store_(std::move(store)), capacity_(capacity) {
  paths_ = read_recent_files(store_, capacity_);
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
  write_recent_files(store_, paths_);  // the list is a convenience: a failed write is not worth a dialog
}

}  // namespace vimg::editor
