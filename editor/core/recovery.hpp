#pragma once
// Crash recovery, one slot per document. The editor autosaves a dirty document at a short
// interval into its slot and offers a slot left behind by an editor that is gone on the next
// start. A clean exit or a save removes the slot.
//
// Layout: DIR/slot-KEY/{document.vimg, origin, lock}. KEY is a hash of the document's absolute
// path, or "new-PID-TIME" for an untitled document. The instance that owns a slot holds an
// exclusive flock on its lock file for as long as it runs, so two editors never write one slot
// (the second editor of the same file takes "slot-KEY-PID"), and a slot whose lock nobody holds
// belongs to an editor that ended without cleaning up: an orphan, offered back. The files are
// written through storage's atomic writer. A recovery.vimg of the old single-slot layout is
// offered as an orphan too.
#include <filesystem>
#include <optional>
#include <string>

#include "primitives/image.hpp"

namespace vimg::editor {

class RecoveryStore {
 public:
  explicit RecoveryStore(std::filesystem::path dir);
  ~RecoveryStore();  // unlocks this instance's slot and leaves it in place (discard() removes it)
  RecoveryStore(const RecoveryStore&) = delete;
  RecoveryStore& operator=(const RecoveryStore&) = delete;

  // The default folder: $XDG_STATE_HOME/vimg-editor, else ~/.local/state/vimg-editor.
  static std::filesystem::path default_dir();

  // Takes the oldest orphaned slot (unlocked, holding a document) as this instance's slot, locked,
  // so that exists(), file() and recorded_origin() describe it. False if there is none.
  bool adopt_orphan();

  // Writes the document and its origin path into the slot of `origin` (empty: untitled),
  // claiming that slot first when the document moved. Returns an error message, or nothing.
  std::optional<std::string> save(const Image& image, const std::filesystem::path& origin);
  // This instance's slot holds a document.
  bool exists() const;
  std::filesystem::path file() const;  // the slot's document (empty before any slot)
  // Which file the slot's document was opened from (empty for an untitled one).
  std::filesystem::path recorded_origin() const;
  // Removes this instance's slot and its files.
  void discard();

  const std::filesystem::path& slot_dir() const { return slot_; }

 private:
  std::optional<std::string> claim(const std::filesystem::path& origin);
  void release() noexcept;

  std::filesystem::path dir_;
  std::filesystem::path slot_;       // empty: no slot yet
  std::filesystem::path slot_origin_;
  int lock_fd_ = -1;
};

}  // namespace vimg::editor
