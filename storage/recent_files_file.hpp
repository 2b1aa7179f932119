#pragma once
// The editor's recent-files store (editor/core/recent_files.hpp): a text file of one absolute path
// a line, most recent first, written atomically. Reading it is bounded: a store over
// kMaxRecentFilesBytes, or one that is not a regular file, reads as empty, and lines that are not
// plausible paths (too long, control characters, not absolute) are skipped, so a damaged or
// hostile store never costs more than that.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vimg {

inline constexpr std::size_t kMaxRecentFilesBytes = 256 * 1024;
inline constexpr std::size_t kMaxRecentPathBytes = 4096;  // PATH_MAX on Linux

// The entries of a store's text, most recent first, without duplicates, at most `capacity`.
std::vector<std::string> parse_recent_files(std::string_view text, std::size_t capacity);
// The same from the store; empty when it is missing or does not read.
std::vector<std::string> read_recent_files(const std::filesystem::path& store, std::size_t capacity);
// Writes the store (creating its folder); the error text, or nothing.
std::optional<std::string> write_recent_files(const std::filesystem::path& store, const std::vector<std::string>& paths);

}  // namespace vimg
