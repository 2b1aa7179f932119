#pragma once
// The document a designer works on, with its file: the editing model (DocumentEditor), the path it
// was opened from or saved to, the problems found when it was opened, the recent-files list,
// autosave into the crash-recovery slot and the recovery of a slot left by a crashed editor.
// No GUI code: the editor's dialogs call these and show the messages they return.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "editor/core/document_editor.hpp"
#include "editor/core/recent_files.hpp"
#include "editor/core/recovery.hpp"
#include "storage/diagnostic.hpp"
#include "storage/import/import.hpp"

namespace vimg::editor {

class DocumentSession {
 public:
  struct Options {
    std::filesystem::path recent_store;  // the recent-files list (one path a line)
    std::filesystem::path recovery_dir;  // RecoveryStore's folder
    double autosave_interval_s = 5.0;
    std::string tool_version;            // written into a new document's meta
  };
  explicit DocumentSession(Options options);

  // A blank page: 100 x 100 mm, meta naming vimg-editor and `tool_version`.
  static Image blank_image(const std::string& tool_version);

  DocumentEditor& editor() { return doc_; }
  const DocumentEditor& editor() const { return doc_; }
  // The file the document belongs to; empty for a new document.
  const std::string& path() const { return path_; }
  // The file's name, or "untitled".
  std::string display_name() const;
  // The problems reported when the document was read (kept until another document replaces it).
  const std::vector<Diagnostic>& load_diagnostics() const { return load_diagnostics_; }
  const RecentFiles& recent() const { return recent_; }

  // Replaces the document with a blank one.
  void new_document();
  // Reads `path`. On success `before_replace` runs, then the document is replaced, the path and
  // the recent-files list updated; on failure the document stays and the message is returned
  // (the path leaves the recent-files list). A file with errors that can still be read opens with
  // every element that could be read, its problems in load_diagnostics() (document_problems.hpp).
  std::optional<std::string> open(const std::string& path, const std::function<void()>& before_replace = {});
  // File -> Import: imports a drawing or picture (storage/import/import.hpp) as a new untitled,
  // unsaved document; its warnings become load_diagnostics(). A PNG that already carries a
  // vibroimage is opened as open() would. On failure the document stays and the errors are
  // returned. `before_replace` as for open().
  std::optional<std::string> import_into_new_document(const std::string& path, const ImportOptions& options,
                                                      const std::function<void()>& before_replace = {});
  // Writes the document (the format by extension, atomically). `becomes_document_path`: the
  // document now belongs to `path` and is saved (Save, Save As); otherwise a copy (Export).
  std::optional<std::string> save_to(const std::string& path, bool becomes_document_path);

  // Writes a dirty document into the recovery slot when `autosave_interval_s` has passed since
  // the last autosave and it changed since. Returns the status to show ("autosaved" or
  // "autosave failed: ..."), nothing when nothing was due. Never while a recovery is pending.
  std::optional<std::string> autosave_if_due(double now_s);

  // Crash recovery. offer_recovery() adopts a slot left by an editor that is gone; while the
  // designer has not chosen (recover or discard), nothing removes or overwrites it.
  bool offer_recovery();
  bool recovery_pending() const { return recovery_pending_; }
  std::filesystem::path recovery_origin() const { return recovery_.recorded_origin(); }
  // Loads the slot's document as unsaved work of its original path; a message on failure.
  std::optional<std::string> recover();
  void discard_recovery();
  // A clean exit: the designer has chosen what to keep.
  void end_session() { recovery_.discard(); }

 private:
  void discard_recovery_unless_pending();

  Options options_;
  DocumentEditor doc_;
  std::string path_;
  std::vector<Diagnostic> load_diagnostics_;
  RecentFiles recent_;
  RecoveryStore recovery_;
  bool recovery_pending_ = false;
  std::uint64_t autosaved_change_ = 0;
  double last_autosave_s_ = 0.0;
};

// What File -> Import asks before importing `path`: whether it is a picture (PNG) and, if so,
// whether it already carries a vibroimage (then it is opened, nothing asked) and its width in mm
// from its pHYs chunk (100 mm when it has none or it cannot be read).
struct ImportQuestion {
  bool picture = false;
  bool vibroimage = false;
  double width_mm = 100.0;
};
ImportQuestion import_question(const std::string& path);

}  // namespace vimg::editor
