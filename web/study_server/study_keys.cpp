#include "web/study_server/study_keys.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <cstring>
#include <string>

#include "storage/study/study_secret_file.hpp"

namespace vimg::web {

std::variant<StudyKeys, std::string> StudyKeys::open(const std::filesystem::path& dir) {
  auto secret = open_study_secret(dir);
  if (auto* error = std::get_if<std::string>(&secret)) return *error;
  return StudyKeys(std::get<StudySecret>(secret));
}

StudyKeys::Key StudyKeys::derive(std::string_view purpose, std::string_view participant) const {
  std::string message = "vimg ";
  message += purpose;
  message += '\0';
  message += participant;
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret_.data(), static_cast<int>(secret_.size()), reinterpret_cast<const unsigned char*>(message.data()),
       message.size(), digest, &length);
  Key key{};
  std::memcpy(key.data(), digest, key.size());  // SHA-256 gives 32 bytes; the first 16 are the key
  return key;
}

std::string StudyKeys::participant_key(std::string_view participant) const {
  const Key key = derive("participant", participant);
  return to_hex(key.data(), key.size());
}

std::string StudyKeys::researcher_key() const {
  const Key key = derive("researcher", "");
  return to_hex(key.data(), key.size());
}

bool StudyKeys::matches(const Key& expected, std::string_view given_hex) {
  Key given{};
  if (!from_hex(given_hex, given.data(), given.size())) return false;
  return CRYPTO_memcmp(expected.data(), given.data(), expected.size()) == 0;
}

bool StudyKeys::is_participant_key(std::string_view participant, std::string_view key) const {
  return matches(derive("participant", participant), key);
}

bool StudyKeys::is_researcher_key(std::string_view key) const { return matches(derive("researcher", ""), key); }

}  // namespace vimg::web
