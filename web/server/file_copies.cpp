#include "web/server/file_copies.hpp"

namespace vimg::web {

namespace {

constexpr std::size_t kSweepAbove = 1024;  // index entries; beyond, those of freed copies go

}  // namespace

FileCopies::FileCopies(std::size_t budget_bytes) : budget_(budget_bytes) {}

void FileCopies::Budget::changed() {
  const std::lock_guard lock(hook_mutex);
  if (hook) hook();
}

void FileCopies::Budget::release(std::size_t bytes) {
  held.fetch_sub(bytes);
  changed();
}

void FileCopies::on_change(std::function<void()> hook) {
  const std::lock_guard lock(budget_state_->hook_mutex);
  budget_state_->hook = std::move(hook);
}

bool FileCopies::reserve(std::size_t bytes) {
  std::atomic<std::size_t>& held_now = budget_state_->held;
  std::size_t held = held_now.load();
  do {
    if (bytes > budget_ || held > budget_ - bytes) return false;
  } while (!held_now.compare_exchange_weak(held, held + bytes));
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
    copy.never_fits = version.size > budget_;
    return copy;
  }
  std::atomic<std::size_t>& held = budget_state_->held;
  std::optional<std::string> bytes = read(copy.error);
  if (!bytes) {
    budget_state_->release(static_cast<std::size_t>(version.size));
    return copy;
  }
  // The file may have changed between its fstat and its read: the budget counts what is held.
  const std::size_t held_bytes = bytes->size();
  if (held_bytes >= version.size) {
    held.fetch_add(held_bytes - static_cast<std::size_t>(version.size));
  } else {
    held.fetch_sub(static_cast<std::size_t>(version.size) - held_bytes);
  }
  copy.bytes = std::shared_ptr<const std::string>(new std::string(std::move(*bytes)),
                                                  [budget = budget_state_, held_bytes](const std::string* text) {
                                                    delete text;
                                                    budget->release(held_bytes);
                                                  });
  {
    const std::lock_guard lock(mutex_);
    if (index_.size() > kSweepAbove) std::erase_if(index_, [](const auto& entry) { return entry.second.bytes.expired(); });
    index_[path] = Entry{version, copy.bytes};
  }
  budget_state_->changed();  // a request waiting for room may share it
  return copy;
}

}  // namespace vimg::web
