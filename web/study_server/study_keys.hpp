#pragma once
// The keys of a study run in the browser (docs/matching-test.md, "The matching test in the browser"). A secret of 256
// random bits lives in the results folder (storage/study/study_secret_file.hpp), made the first
// time `vimg serve --study` or `vimg study link` needs it. Every key is derived from it, so links
// stay valid across restarts and nothing else is stored:
//   participant key  HMAC-SHA256(secret, "vimg participant\0" + ID), first 128 bits, 32 hex digits
//   researcher key   HMAC-SHA256(secret, "vimg researcher\0"),      first 128 bits, 32 hex digits
// A key given by a request is compared in constant time (CRYPTO_memcmp) with the one derived.
// A secret file that the storage refuses stops the study before it starts.
#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>

#include "storage/study/study_secret_file.hpp"

namespace vimg::web {

inline constexpr std::size_t kStudyKeyBytes = 16;  // 128 bits: 32 hex digits in a link

class StudyKeys {
 public:
  // Reads DIR's secret, or makes it when there is none. The error names the file.
  static std::variant<StudyKeys, std::string> open(const std::filesystem::path& dir);
  // A key from given secret bytes (tests).
  explicit StudyKeys(const StudySecret& secret) : secret_(secret) {}

  std::string participant_key(std::string_view participant) const;
  std::string researcher_key() const;
  // Constant-time comparisons; false for text that is not 32 hex digits.
  bool is_participant_key(std::string_view participant, std::string_view key) const;
  bool is_researcher_key(std::string_view key) const;

 private:
  using Key = std::array<unsigned char, kStudyKeyBytes>;
  Key derive(std::string_view purpose, std::string_view participant) const;
  static bool matches(const Key& expected, std::string_view given_hex);
  StudySecret secret_{};
};

}  // namespace vimg::web
