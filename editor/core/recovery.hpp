#pragma once
// Crash recovery: the editor autosaves a dirty document to a recovery file at a short interval
// (atomically, through storage) and offers it back on the next start. A clean exit or a save
// removes it.
#include <filesystem>
#include <optional>
#include <string>

#include "primitives/image.hpp"

namespace vimg::editor {

class RecoveryStore {
 public:
  explicit RecoveryStore(std::filesystem::path dir);

  // The default folder: $XDG_STATE_HOME/vimg-editor, else ~/.local/state/vimg-editor.
  static std::filesystem::path default_dir();

  std::filesystem::path file() const { return dir_ / "recovery.vimg"; }
  // Which file the recovered document was opened from (empty for a new one).
  std::filesystem::path origin_file() const { return dir_ / "recovery.origin"; }

  // Writes the document and its origin path. Returns an error message, or nothing on success.
  std::optional<std::string> save(const Image& image, const std::filesystem::path& origin);
  bool exists() const;
  std::filesystem::path recorded_origin() const;
  void discard();

 private:
  std::filesystem::path dir_;
};

}  // namespace vimg::editor
