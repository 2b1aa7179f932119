#pragma once
// Writing a file so that readers see either the old content or the complete new one (spec
// section 4): a temporary file in the same directory, written, flushed and fsync'ed, then renamed
// over the target.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vimg {

// Returns an error message naming the path, or nothing on success. The temporary file is removed
// on failure.
std::optional<std::string> write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace vimg
