#include "storage/line_file.hpp"

#include "storage/atomic_file.hpp"

namespace vimg {

std::optional<std::string> write_line_file(const std::filesystem::path& file, const std::string& line) {
  return write_file_atomically(file, line + "\n");
}

LineFileRead read_line_file(const std::filesystem::path& file, std::size_t max_bytes, FinalSymlink final_symlink) {
  LineFileRead result;
  const FileReadResult read = read_regular_file(file, max_bytes, final_symlink);
  if (!read.bytes) {
    result.error = read.error;
    return result;
  }
  std::string line = read.bytes->substr(0, read.bytes->find('\n'));
  if (!line.empty() && line.back() == '\r') line.pop_back();
  result.line = std::move(line);
  return result;
}

}  // namespace vimg
