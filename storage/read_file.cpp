#include "storage/read_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

namespace vimg {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string size_text(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= 1024 && bytes % 1024 == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

FileReadResult read_regular_file(const std::filesystem::path& path, std::size_t max_bytes, FinalSymlink final_symlink) {
  FileReadResult result;
  const int no_follow = final_symlink == FinalSymlink::refuse ? O_NOFOLLOW : 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY | no_follow);
  if (fd < 0) {
    if (errno == ELOOP && no_follow != 0) result.error = "is a symbolic link (name the file itself)";
    else result.error = std::string("cannot open: ") + std::strerror(errno);
    return result;
  }
  result = read_open_file(fd, max_bytes);
  ::close(fd);
  return result;
}

FileReadResult read_open_file(int fd, std::size_t max_bytes) {
  FileReadResult result;
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    result.error = std::string("cannot read: ") + std::strerror(errno);
  } else if (!S_ISREG(st.st_mode)) {
    result.error = std::string("is not a regular file (") + kind_of(st.st_mode) + ")";
  } else if (static_cast<std::uint64_t>(st.st_size) > max_bytes) {
    result.error = "is larger than " + size_text(max_bytes) + " (limit " + std::to_string(max_bytes) + " bytes)";
  }
  if (!result.error.empty()) return result;
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t filled = 0;
  for (;;) {
    if (filled == bytes.size()) {
      if (bytes.size() > max_bytes) break;            // it grew past the limit while we read
      bytes.resize(std::min(max_bytes + 1, bytes.size() + 65536));  // it may have grown since fstat
      if (filled == bytes.size()) break;
    }
    const ssize_t n = ::pread(fd, bytes.data() + filled, bytes.size() - filled, static_cast<off_t>(filled));
    if (n < 0) {
      if (errno == EINTR) continue;
      result.error = std::string("cannot read: ") + std::strerror(errno);
      return result;
    }
    if (n == 0) break;
    filled += static_cast<std::size_t>(n);
  }
  if (filled > max_bytes) {
    result.error = "is larger than " + size_text(max_bytes) + " (limit " + std::to_string(max_bytes) + " bytes)";
    return result;
  }
  bytes.resize(filled);
  result.bytes = std::move(bytes);
  return result;
}

}  // namespace vimg
