#pragma once
// The bytes of the site's files while replies send them (docs/web.md, "Connections"): one copy per
// file, shared by every reply of it (4000 pages fetching the 200 KB wasm hold 200 KB, not 800 MB),
// and a budget on the bytes all copies hold at once. A copy lives while a reply holds it: the
// last reply's write done (or its connection closed), it is freed and its bytes leave the budget.
// A file rewritten since (another inode, size or time) gets a copy of its own; the old one lives
// on for the replies still sending it. A copy that would pass the budget is not made: the request
// gets 503 with Retry-After, and nothing waits.
// Threads: any (the routes' workers); the budget is atomic, the index is locked.
#include <sys/types.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

namespace vimg::web {

// What tells one version of a file from the next (fstat's fields).
struct FileVersion {
  dev_t device = 0;
  ino_t inode = 0;
  std::uint64_t size = 0;
  std::int64_t modified_ns = 0, changed_ns = 0;
  bool operator==(const FileVersion&) const = default;
};

class FileCopies {
 public:
  explicit FileCopies(std::size_t budget_bytes);

  struct Copy {
    std::shared_ptr<const std::string> bytes;  // set when the reply can be sent
    bool over_budget = false;                  // no room in the budget now: 503
    std::string error;                         // the file could not be read (from `read`)
  };
  // The copy of `path` at `version`: the one a reply holds already, or one read now by `read`
  // (which returns the bytes or sets the error) once the budget has room for `version.size` bytes.
  Copy acquire(const std::string& path, const FileVersion& version,
               const std::function<std::optional<std::string>(std::string& error)>& read);

  std::size_t held_bytes() const { return held_->load(); }
  std::size_t budget_bytes() const { return budget_; }

 private:
  struct Entry {
    FileVersion version;
    std::weak_ptr<const std::string> bytes;
  };
  bool reserve(std::size_t bytes);
  std::size_t budget_;
  // Shared with each copy's deleter, which gives its bytes back (a copy may outlive this index).
  std::shared_ptr<std::atomic<std::size_t>> held_ = std::make_shared<std::atomic<std::size_t>>(0);
  std::mutex mutex_;
  std::unordered_map<std::string, Entry> index_;
};

}  // namespace vimg::web
