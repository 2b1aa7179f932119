// Fuzzes the editor's recent-files list parser: any bytes give at most `capacity` distinct,
// absolute, printable paths no longer than the limit, never a crash.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/recent_files_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto paths = vimg::parse_recent_files(text, 10);
  if (paths.size() > 10) std::abort();
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string& p = paths[i];
    if (p.empty() || p.front() != '/' || p.size() > vimg::kMaxRecentPathBytes) std::abort();
    if (std::any_of(p.begin(), p.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; })) std::abort();
    if (std::find(paths.begin(), paths.begin() + static_cast<std::ptrdiff_t>(i), p) != paths.begin() + static_cast<std::ptrdiff_t>(i)) std::abort();
  }
  return 0;
}
