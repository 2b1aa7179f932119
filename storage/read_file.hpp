#pragma once
// The one way the project reads a whole file named by a user or by another file. Before reading
// anything it refuses what is not a regular file (a FIFO, which would block; a device such as
// /dev/zero, which never ends; a directory) and anything larger than `max_bytes`, so a path can
// never make a reader hang or allocate without bound. The open never blocks (O_NONBLOCK).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace vimg {

struct FileReadResult {
  std::optional<std::string> bytes;  // set on success
  // On failure, the problem without the path, e.g. "is not a regular file (a FIFO)" or
  // "is larger than 64 MiB (limit 67108864 bytes)"; the caller prefixes the file name.
  std::string error;
};

// Whether the last component of the path may be a symbolic link. Paths named inside files refuse
// it (read_named_file): the link, not its target, is what the file's author controls.
enum class FinalSymlink { follow, refuse };

FileReadResult read_regular_file(const std::filesystem::path& path, std::size_t max_bytes,
                                 FinalSymlink final_symlink = FinalSymlink::follow);

// The same checks and read on a file the caller has already opened (and keeps open): the trial log
// (storage/study/trial_log.hpp) reads the file it holds locked and appends to. Reads from offset 0
// whatever the descriptor's position; the descriptor stays open.
FileReadResult read_open_file(int fd, std::size_t max_bytes);

}  // namespace vimg
