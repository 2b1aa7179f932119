#include "editor/core/recent_files.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

namespace vimg::editor {

RecentFiles::RecentFiles(std::filesystem::path store, std::size_t capacity)
    : store_(std::move(store)), capacity_(capacity) {
  std::ifstream in(store_);
  std::string line;
  while (paths_.size() < capacity_ && std::getline(in, line)) {
    if (!line.empty() && std::find(paths_.begin(), paths_.end(), line) == paths_.end()) paths_.push_back(line);
  }
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
  std::ofstream out(store_, std::ios::trunc);
  for (const std::string& p : paths_) out << p << '\n';
}

}  // namespace vimg::editor
