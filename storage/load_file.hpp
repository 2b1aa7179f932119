#pragma once
// The one sequence by which a loader turns a path into a parsed value: read the whole file within
// its limit (read_regular_file: a FIFO, a device, a directory or an oversize file is refused before
// anything is read), and when that fails return a Result whose only diagnostic is the read error,
// at line 0 ("FILE: error: is not a regular file (a FIFO)"); else parse the bytes under the name
// the user gave. Result is any loader result with a `std::vector<Diagnostic> diagnostics` member.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "storage/diagnostic.hpp"
#include "storage/read_file.hpp"

namespace vimg {

template <class Result, class Parse>
Result load_file(const std::filesystem::path& path, std::size_t max_bytes, Parse&& parse) {
  const FileReadResult read = read_regular_file(path, max_bytes);
  if (!read.bytes) {
    Result failed;
    failed.diagnostics.push_back(Diagnostic{Diagnostic::Severity::error, path.string(), 0, read.error});
    return failed;
  }
  return std::forward<Parse>(parse)(std::string_view(*read.bytes), path.string());
}

}  // namespace vimg
