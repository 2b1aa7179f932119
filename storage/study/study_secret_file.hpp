#pragma once
// The secret of a study run in the browser (docs/studies.md, "In the browser"): 256 random bits
// (getrandom) in the results folder, DIR/vimg-study.secret, as 64 hex digits and a newline, mode
// 0600, written atomically (storage/atomic_file.hpp) the first time a program needs it, under an
// flock() of DIR so that two programs never make two. web/study_server/study_keys.hpp derives every
// key from it. A secret file that is a symbolic link, is not a regular file of this user, is
// readable or writable by others, or does not hold exactly 64 hex digits is refused.
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

namespace vimg {

inline constexpr const char* kStudySecretFile = "vimg-study.secret";
inline constexpr std::size_t kStudySecretBytes = 32;
using StudySecret = std::array<unsigned char, kStudySecretBytes>;

// Reads DIR's secret, or makes it when there is none. The error names the file (or DIR).
std::variant<StudySecret, std::string> open_study_secret(const std::filesystem::path& dir);

// Lower-case hex of bytes, and back (false when `hex` is not 2 * size hex digits).
std::string to_hex(const unsigned char* bytes, std::size_t size);
bool from_hex(std::string_view hex, unsigned char* bytes, std::size_t size);

}  // namespace vimg
