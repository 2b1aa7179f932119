#include "storage/study/study_secret_file.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "storage/atomic_file.hpp"
#include "storage/read_file.hpp"

namespace vimg {

std::string to_hex(const unsigned char* bytes, std::size_t size) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string hex;
  for (std::size_t i = 0; i < size; ++i) {
    hex += kDigits[bytes[i] >> 4];
    hex += kDigits[bytes[i] & 15];
  }
  return hex;
}

bool from_hex(std::string_view hex, unsigned char* bytes, std::size_t size) {
  if (hex.size() != 2 * size) return false;
  const auto digit = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  for (std::size_t i = 0; i < size; ++i) {
    const int high = digit(hex[2 * i]), low = digit(hex[2 * i + 1]);
    if (high < 0 || low < 0) return false;
    bytes[i] = static_cast<unsigned char>(high * 16 + low);
  }
  return true;
}

namespace {

namespace fs = std::filesystem;

// Holds an flock() of a folder while the secret is looked for and made.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& dir) : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ >= 0) {
      while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {}
    }
  }
  ~FolderLock() {
    if (fd_ >= 0) ::close(fd_);
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  bool ok() const { return fd_ >= 0; }

 private:
  int fd_;
};

// The secret file's bytes, checked: nullopt when it does not exist; the error text when it is not
// a private regular file of this user.
std::variant<std::monostate, std::string, StudySecret> read_secret(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0 && errno == ENOENT) return std::monostate{};
  const std::string where = file.string() + ": error: ";
  if (fd < 0) return where + (errno == ELOOP ? std::string("is a symbolic link") : "cannot open: " + std::string(std::strerror(errno)));
  struct stat st {};
  std::string problem;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    problem = "is not a regular file";
  } else if (st.st_uid != ::geteuid()) {
    problem = "belongs to another user";
  } else if ((st.st_mode & 077) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    problem = std::string("has mode ") + mode + ": the study's secret must be private (chmod 600 " + file.string() + ")";
  }
  FileReadResult read;
  if (problem.empty()) read = read_open_file(fd, 2 * kStudySecretBytes + 1);
  ::close(fd);
  if (!problem.empty()) return where + problem;
  if (!read.bytes) return where + read.error;
  std::string text = *read.bytes;
  if (!text.empty() && text.back() == '\n') text.pop_back();
  StudySecret secret{};
  if (!from_hex(text, secret.data(), secret.size())) return where + "does not hold the 64 hex digits of a study secret";
  return secret;
}

}  // namespace

std::variant<StudySecret, std::string> open_study_secret(const fs::path& dir) {
  const fs::path file = dir / kStudySecretFile;
  FolderLock lock(dir);
  if (!lock.ok()) return dir.string() + ": error: cannot open the results folder: " + std::strerror(errno);
  auto existing = read_secret(file);
  if (auto* secret = std::get_if<StudySecret>(&existing)) return *secret;
  if (auto* error = std::get_if<std::string>(&existing)) return *error;
  StudySecret secret{};
  std::size_t filled = 0;
  while (filled < secret.size()) {
    const ssize_t n = ::getrandom(secret.data() + filled, secret.size() - filled, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return file.string() + ": error: no random bytes for the study's secret: " + std::strerror(errno);
    filled += static_cast<std::size_t>(n);
  }
  if (const auto error = write_file_atomically(file, to_hex(secret.data(), secret.size()) + "\n", NewFileMode{0600})) {
    return *error;
  }
  return secret;
}

}  // namespace vimg
