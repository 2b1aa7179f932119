#pragma once
// The keys of a study run in the browser (docs/studies.md, "In the browser"). A secret of 256
// random bits (getrandom) lives in the results folder, DIR/vimg-study.secret, as 64 hex digits,
// mode 0600, written atomically (storage/atomic_file.hpp) the first time `vimg serve --study` or
// `vimg study link` needs it, under an flock() of DIR so that two programs never make two. Every
// key is derived from it, so links stay valid across restarts and nothing else is stored:
//   participant key  HMAC-SHA256(secret, "vimg participant\0" + ID), first 128 bits, 32 hex digits
//   researcher key   HMAC-SHA256(secret, "vimg researcher\0"),      first 128 bits, 32 hex digits
// A key given by a request is compared in constant time (CRYPTO_memcmp) with the one derived.
// A secret file that is not a regular file of this user, is readable or writable by others, or
// does not hold exactly 64 hex digits is refused (the study does not start).
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

namespace vimg::web {

inline constexpr const char* kStudySecretFile = "vimg-study.secret";
inline constexpr std::size_t kStudySecretBytes = 32;
inline constexpr std::size_t kStudyKeyBytes = 16;  // 128 bits: 32 hex digits in a link

class StudyKeys {
 public:
  // Reads DIR's secret, or makes it when there is none. The error names the file.
  static std::variant<StudyKeys, std::string> open(const std::filesystem::path& dir);
  // A key from given secret bytes (tests).
  explicit StudyKeys(const std::array<unsigned char, kStudySecretBytes>& secret) : secret_(secret) {}

  std::string participant_key(std::string_view participant) const;
  std::string researcher_key() const;
  // Constant-time comparisons; false for text that is not 32 hex digits.
  bool is_participant_key(std::string_view participant, std::string_view key) const;
  bool is_researcher_key(std::string_view key) const;

 private:
  using Key = std::array<unsigned char, kStudyKeyBytes>;
  Key derive(std::string_view purpose, std::string_view participant) const;
  static bool matches(const Key& expected, std::string_view given_hex);
  std::array<unsigned char, kStudySecretBytes> secret_{};
};

// Lower-case hex of bytes, and back (false when `hex` is not 2 * size hex digits).
std::string to_hex(const unsigned char* bytes, std::size_t size);
bool from_hex(std::string_view hex, unsigned char* bytes, std::size_t size);

}  // namespace vimg::web
