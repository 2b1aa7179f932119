#pragma once
// What the output's device says while the editor plays (play_output.hpp), shown to the designer as
// vimg-player shows it on its overlay: every message on stderr as "vimg-editor: MESSAGE", and the
// newest in the status bar after what the editor is doing ("playing to drv2605l:/dev/i2c-1:
// /dev/i2c-1: over-current ..."), until something else takes the status bar. GUI thread.
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "editor/notices.hpp"

namespace vimg::editor {

// Shows `messages` (oldest first); `doing` is what the status bar said before them ("playing to
// OUTPUT", "drawing"). Returns how many were shown.
std::size_t show_device_messages(const std::vector<std::string>& messages, const std::string& doing, Notices& notices,
                                 std::FILE* log = stderr);

}  // namespace vimg::editor
