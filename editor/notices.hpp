#pragma once
// What the parts of the editor tell the designer: the status line and the problem dialog.
// The app shows both; any part may write them (GUI thread only).
#include <cstdio>
#include <string>

namespace vimg::editor {

struct Notices {
  std::string status;         // the right end of the status bar
  std::string error_message;  // the text of the "Problem" dialog
  bool error_opening = false; // the dialog opens on the next frame

  // Shows `message` in the problem dialog and prints it on stderr.
  void report_error(std::string message) {
    std::fprintf(stderr, "%s\n", message.c_str());
    error_message = std::move(message);
    error_opening = true;
  }
};

}  // namespace vimg::editor
