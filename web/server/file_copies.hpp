#pragma once
// The bytes of the site's files while replies send them (docs/web-serving.md, "Connections"): one copy per
// file, shared by every reply of it (4000 pages fetching the 200 KB wasm hold 200 KB, not 800 MB),
// and a budget on the bytes all copies hold at once. A copy lives while a reply holds it: the
// last reply's write done (or its connection closed), it is freed and its bytes leave the budget.
// A file rewritten since (another inode, size or time) gets a copy of its own; the old one lives
// on for the replies still sending it. A copy that would pass the budget is not made: the caller
// is told (over_budget), and may try again when on_change() says a copy's bytes have left the
// budget or a copy was made that it may share (the server's request then waits for room, holding
// nothing: web/server/http_engine.hpp).
// Threads: any (the routes' workers; a copy is freed on whichever thread drops it last); the budget
// is atomic, the index and the hook are locked.
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

  // Called each time a copy's bytes leave the budget (from the thread that frees it) and each time a
  // copy is made (from acquire's); empty: nothing.
  // Set before the first acquire and cleared before whatever it calls goes away.
  void on_change(std::function<void()> hook);

  struct Copy {
    std::shared_ptr<const std::string> bytes;  // set when the reply can be sent
    bool over_budget = false;                  // no room in the budget now (room may come)
    bool never_fits = false;                   // larger than the whole budget (with over_budget)
    std::string error;                         // the file could not be read (from `read`)
  };
  // The copy of `path` at `version`: the one a reply holds already, or one read now by `read`
  // (which returns the bytes or sets the error) once the budget has room for `version.size` bytes.
  Copy acquire(const std::string& path, const FileVersion& version,
               const std::function<std::optional<std::string>(std::string& error)>& read);

  std::size_t held_bytes() const { return budget_state_->held.load(); }
  std::size_t budget_bytes() const { return budget_; }

 private:
  struct Entry {
    FileVersion version;
    std::weak_ptr<const std::string> bytes;
  };
  // The bytes held, and the hook told when some leave: shared with each copy's deleter, which
  // gives its bytes back (a copy may outlive this index).
  struct Budget {
    std::atomic<std::size_t> held{0};
    std::mutex hook_mutex;
    std::function<void()> hook;
    void changed();  // calls the hook
    void release(std::size_t bytes);
  };
  bool reserve(std::size_t bytes);
  std::size_t budget_;
  std::shared_ptr<Budget> budget_state_ = std::make_shared<Budget>();
  std::mutex mutex_;
  std::unordered_map<std::string, Entry> index_;
};

}  // namespace vimg::web
