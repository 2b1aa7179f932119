#pragma once
// A file that holds one line of text (a path, an address) beside a program's data: the editor's
// recovery slot names its document's origin in one, `vimg serve --study` records the address it
// serves at in another. Written atomically with a line end; read through the bounded reader (a
// FIFO, a device or a file over `max_bytes` is refused), as its first line without the line end.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "storage/read_file.hpp"

namespace vimg {

// The error text, or nothing.
std::optional<std::string> write_line_file(const std::filesystem::path& file, const std::string& line);

struct LineFileRead {
  std::optional<std::string> line;  // the first line, without '\n' or "\r\n"
  std::string error;                // why it did not read, without the file name
};
LineFileRead read_line_file(const std::filesystem::path& file, std::size_t max_bytes,
                            FinalSymlink final_symlink = FinalSymlink::follow);

}  // namespace vimg
