#include "editor/core/recovery.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <system_error>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/line_file.hpp"

namespace vimg::editor {
namespace {

constexpr const char* kDocument = "document.vimg";
constexpr const char* kOrigin = "origin";
constexpr std::size_t kMaxOriginFileBytes = 4096 + 2;  // PATH_MAX and the line end
constexpr const char* kLock = "lock";
constexpr const char* kLegacyDocument = "recovery.vimg";
constexpr const char* kLegacyOrigin = "recovery.origin";

std::string hex64(std::uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = digits[v & 15];
  return s;
}

// FNV-1a: a stable key for a path (no security role: the lock decides ownership).
std::string path_key(const std::filesystem::path& path) {
  std::uint64_t h = 1469598103934665603ull;
  for (const unsigned char c : path.string()) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return hex64(h);
}

std::filesystem::path absolute_of(const std::filesystem::path& p) {
  std::error_code ec;
  const auto a = std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec);
  return ec ? p : a;
}

// Opens and exclusively locks DIR/lock without waiting; -1 if another process holds it.
int lock_slot(const std::filesystem::path& slot) {
  const int fd = ::open((slot / kLock).c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
  if (fd < 0) return -1;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// The slot's origin: one line naming the document's path (empty: untitled, or unreadable).
std::string read_origin(const std::filesystem::path& file) {
  return read_line_file(file, kMaxOriginFileBytes).line.value_or(std::string());
}

}  // namespace

RecoveryStore::RecoveryStore(std::filesystem::path dir) : dir_(std::move(dir)) {}

RecoveryStore::~RecoveryStore() { release(); }

std::filesystem::path RecoveryStore::default_dir() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state) {
    return std::filesystem::path(state) / "vimg-editor";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".local" / "state" / "vimg-editor";
  }
  return std::filesystem::temp_directory_path() / "vimg-editor";
}

void RecoveryStore::release() noexcept {
  if (lock_fd_ >= 0) {
    ::close(lock_fd_);  // closing drops the flock
    lock_fd_ = -1;
  }
  slot_.clear();
  slot_origin_.clear();
}

std::optional<std::string> RecoveryStore::claim(const std::filesystem::path& origin) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) return dir_.string() + ": cannot create the recovery folder: " + ec.message();
  std::string key;
  if (origin.empty()) {
    key = "new-" + std::to_string(::getpid()) + "-" +
          std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
  } else {
    key = path_key(absolute_of(origin));
  }
  // The same file open in another editor: take a slot of our own beside it.
  for (const std::string& name : {"slot-" + key, "slot-" + key + "-" + std::to_string(::getpid())}) {
    const std::filesystem::path slot = dir_ / name;
    std::filesystem::create_directories(slot, ec);
    if (ec) return slot.string() + ": cannot create the recovery slot: " + ec.message();
    const int fd = lock_slot(slot);
    if (fd < 0) continue;
    release();
    lock_fd_ = fd;
    slot_ = slot;
    slot_origin_ = origin;
    return std::nullopt;
  }
  return dir_.string() + ": every recovery slot for this document is in use";
}

bool RecoveryStore::adopt_orphan() {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir_, ec)) return false;
  // The old single-slot layout: move its files into a slot of their own first.
  if (std::filesystem::is_regular_file(dir_ / kLegacyDocument, ec)) {
    const std::filesystem::path slot = dir_ / ("slot-legacy-" + std::to_string(::getpid()));
    std::filesystem::create_directories(slot, ec);
    std::filesystem::rename(dir_ / kLegacyDocument, slot / kDocument, ec);
    if (!ec) std::filesystem::rename(dir_ / kLegacyOrigin, slot / kOrigin, ec);
  }
  struct Candidate {
    std::filesystem::file_time_type written;
    std::filesystem::path slot;
  };
  std::vector<Candidate> candidates;
  for (const auto& entry : std::filesystem::directory_iterator(dir_, ec)) {
    if (!entry.is_directory() || entry.path().filename().string().rfind("slot-", 0) != 0) continue;
    if (entry.path() == slot_) continue;
    std::error_code time_ec;
    const auto written = std::filesystem::last_write_time(entry.path() / kDocument, time_ec);
    if (time_ec) continue;  // no document in it
    candidates.push_back({written, entry.path()});
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.written < b.written; });
  for (const Candidate& c : candidates) {
    const int fd = lock_slot(c.slot);
    if (fd < 0) continue;  // its editor is still running
    release();
    lock_fd_ = fd;
    slot_ = c.slot;
    slot_origin_ = read_origin(c.slot / kOrigin);
    return true;
  }
  return false;
}

std::optional<std::string> RecoveryStore::save(const Image& image, const std::filesystem::path& origin) {
  const bool moved = slot_.empty() || origin != slot_origin_;
  if (moved) {
    // The document has a new home: its old slot is obsolete.
    if (!slot_.empty()) discard();
    if (auto error = claim(origin)) return error;
  }
  if (auto error = write_line_file(slot_ / kOrigin, origin.string())) return error;
  return save_image_file(image, slot_ / kDocument);
}

bool RecoveryStore::exists() const {
  std::error_code ec;
  return !slot_.empty() && std::filesystem::is_regular_file(slot_ / kDocument, ec);
}

std::filesystem::path RecoveryStore::file() const { return slot_.empty() ? std::filesystem::path() : slot_ / kDocument; }

std::filesystem::path RecoveryStore::recorded_origin() const {
  return slot_.empty() ? std::filesystem::path() : std::filesystem::path(read_origin(slot_ / kOrigin));
}

void RecoveryStore::discard() {
  if (slot_.empty()) return;
  std::error_code ec;
  std::filesystem::remove(slot_ / kDocument, ec);
  std::filesystem::remove(slot_ / kOrigin, ec);
  std::filesystem::remove(slot_ / kLock, ec);
  std::filesystem::remove(slot_, ec);
  release();
}

}  // namespace vimg::editor
