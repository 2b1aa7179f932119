#include "web/server/file_copies.hpp"

namespace vimg::web {

namespace {

constexpr std::size_t kSweepAbove = 1024;  // index entries; beyond, those of freed copies go

}  // namespace

FileCopies::FileCopies(std::size_t budget_bytes) : budget_(budget_bytes) {}

bool FileCopies::reserve(std::size_t bytes) {
  std::size_t held = held_->load();
  do {
    if (bytes > budget_ || held > budget_ - bytes) return false;
  } while (!held_->compare_exchange_weak(held, held + bytes));
  return true;
}

FileCopies::Copy FileCopies::acquire(const std::string& path, const FileVersion& version,
                                     const std::function<std::optional<std::string>(std::string& error)>& read) {
  Copy copy;
  {
    const std::lock_guard lock(mutex_);
    const auto found = index_.find(path);
    if (found != index_.end() && found->second.version == version) copy.bytes = found->second.bytes.lock();
  }
  if (copy.bytes) return copy;
  if (!reserve(static_cast<std::size_t>(version.size))) {
    copy.over_budget = true;
    return copy;
  }
  std::optional<std::string> bytes = read(copy.error);
  if (!bytes) {
    held_->fetch_sub(static_cast<std::size_t>(version.size));
    return copy;
  }
  // The file may have changed between its fstat and its read: the budget counts what is held.
  const std::size_t held_bytes = bytes->size();
  if (held_bytes >= version.size) {
    held_->fetch_add(held_bytes - static_cast<std::size_t>(version.size));
  } else {
    held_->fetch_sub(static_cast<std::size_t>(version.size) - held_bytes);
  }
  copy.bytes = std::shared_ptr<const std::string>(new std::string(std::move(*bytes)),
                                                  [held = held_, held_bytes](const std::string* text) {
                                                    held->fetch_sub(held_bytes);
                                                    delete text;
                                                  });
  const std::lock_guard lock(mutex_);
  if (index_.size() > kSweepAbove) std::erase_if(index_, [](const auto& entry) { return entry.second.bytes.expired(); });
  index_[path] = Entry{version, copy.bytes};
  return copy;
}

}  // namespace vimg::web
