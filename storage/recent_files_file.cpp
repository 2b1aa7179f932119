#include "storage/recent_files_file.hpp"

#include <algorithm>
#include <system_error>

#include "storage/atomic_file.hpp"
#include "storage/read_file.hpp"

namespace vimg {

std::vector<std::string> parse_recent_files(std::string_view text, std::size_t capacity) {
  std::vector<std::string> paths;
  while (!text.empty() && paths.size() < capacity) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    const bool plausible = !line.empty() && line.size() <= kMaxRecentPathBytes && line.front() == '/' &&
                           std::none_of(line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
    if (plausible && std::find(paths.begin(), paths.end(), line) == paths.end()) paths.emplace_back(line);
  }
  return paths;
}

std::vector<std::string> read_recent_files(const std::filesystem::path& store, std::size_t capacity) {
  const FileReadResult read = read_regular_file(store, kMaxRecentFilesBytes);
  return read.bytes ? parse_recent_files(*read.bytes, capacity) : std::vector<std::string>{};
}

std::optional<std::string> write_recent_files(const std::filesystem::path& store, const std::vector<std::string>& paths) {
  std::error_code ec;
  std::filesystem::create_directories(store.parent_path(), ec);
  std::string text;
  for (const std::string& p : paths) text += p + '\n';
  return write_file_atomically(store, text);
}

}  // namespace vimg
