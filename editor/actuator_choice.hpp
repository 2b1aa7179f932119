#pragma once
// The Actuator choice in the tools panel: which actuator the editor designs for. A combo lists
// the built-in ideal actuator, the profiles shipped in assets/profiles (of the working folder, as
// `--actuator assets/profiles/...` is resolved, else of the source tree) and "Open profile...",
// which opens the file chooser. A profile with errors leaves the choice as it was and shows its
// FILE:LINE messages in the Problem dialog. The choice is remembered in the config folder
// (actuator.txt beside the recent folders, one absolute path, a RecentFiles list of one; none for
// the ideal actuator) and used at the next start without --actuator. GUI thread.
#include <filesystem>
#include <string>
#include <vector>

#include "editor/core/actuator_feel.hpp"
#include "editor/core/recent_files.hpp"
#include "editor/file_chooser.hpp"
#include "editor/notices.hpp"

namespace vimg::editor {

class LayoutLog;

class ActuatorChoice {
 public:
  ActuatorChoice(ActuatorFeel& feel, Notices& notices, LayoutLog& layout, std::filesystem::path recent_folders_store);

  // Uses the profile at `path`; on errors reports them and keeps the current one. True on success.
  bool choose(const std::filesystem::path& path);
  // Uses the profile chosen last time, if any (at start, without --actuator).
  void restore();
  // The combo and, when asked for, the file chooser.
  void draw();

 private:
  ActuatorFeel& feel_;
  Notices& notices_;
  LayoutLog& layout_;
  FileChooser chooser_;
  RecentFiles remembered_;
  std::vector<std::filesystem::path> shipped_;
};

}  // namespace vimg::editor
