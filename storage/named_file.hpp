#pragma once
// The one way to read a file whose path is named inside another file (a volume scene's `file=`):
//   - the name is resolved relative to the naming file's folder;
//   - it may not lead out of that folder (an absolute path, `..` past the folder, a symbolic link
//     to a folder elsewhere) unless the caller explicitly allows it;
//   - the file itself may not be a symbolic link, and must be a regular file within `max_bytes`
//     (read_regular_file: opened with O_NOFOLLOW | O_NONBLOCK, checked with fstat, so a FIFO or a
//     device is refused without ever blocking or reading).
#include <cstddef>
#include <filesystem>
#include <string_view>

#include "storage/read_file.hpp"

namespace vimg {

struct NamedFileOptions {
  // Lets the name lead anywhere (still a regular file, not a symlink, within the limit). Set only on
  // the user's explicit request, never by what a file says.
  bool allow_outside_folder = false;
};

struct NamedFileReadResult {
  std::filesystem::path path;  // the resolved path (for messages)
  FileReadResult read;         // the bytes, or the problem ("leads outside …", "is a FIFO", …)
};

// `folder` is the folder of the naming file ("" for the current directory); `what_folder` names it
// in messages, e.g. "the scene's folder".
NamedFileReadResult read_named_file(const std::filesystem::path& folder, std::string_view name, std::size_t max_bytes,
                                    const NamedFileOptions& options, std::string_view what_folder);

}  // namespace vimg
