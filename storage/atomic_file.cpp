#include "storage/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>

namespace vimg {

namespace {

std::filesystem::path folder_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter.fetch_add(1));
  return folder_of(path) / name;
}

// The registry of pending temporaries: fixed slots of fixed buffers, claimed and released with
// atomics only, read by a signal handler. A slot is free, being written or read by its owner
// (busy), or armed (its path is complete and may be unlinked by the handler).
enum SlotState : int { kFree = 0, kBusy = 1, kArmed = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX] = {};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");
std::array<Slot, kMaxPendingTemporaries> g_slots;

int register_temporary(const std::filesystem::path& temp) {
  const std::string& text = temp.native();
  if (text.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kMaxPendingTemporaries; ++i) {
    Slot& slot = g_slots[static_cast<std::size_t>(i)];
    int expected = kFree;
    if (!slot.state.compare_exchange_strong(expected, kBusy, std::memory_order_acquire)) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.state.store(kArmed, std::memory_order_release);
    return i;
  }
  return -1;
}

void unregister_temporary(int& index) noexcept {
  if (index < 0) return;
  g_slots[static_cast<std::size_t>(index)].state.store(kFree, std::memory_order_release);
  index = -1;
}

// Blocks SIGINT and SIGTERM for the scope: a temporary is created and registered as one step, so
// that a signal never finds it created but not yet registered.
class BlockInterrupts {
 public:
  BlockInterrupts() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, &previous_);
  }
  ~BlockInterrupts() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  BlockInterrupts(const BlockInterrupts&) = delete;
  BlockInterrupts& operator=(const BlockInterrupts&) = delete;

 private:
  sigset_t previous_{};
};

// 128 + the signal: 130 for SIGINT, 143 for SIGTERM (cmdline::kExitSigint, kExitSigterm).
extern "C" void exit_removing_temporaries(int signal_number) {
  remove_pending_temporaries();
  ::_exit(128 + signal_number);
}

}  // namespace

void remove_pending_temporaries() noexcept {
  for (Slot& slot : g_slots) {
    if (slot.state.load(std::memory_order_acquire) == kArmed) ::unlink(slot.path);
  }
}

void exit_on_interrupt_removing_temporaries() {
  struct sigaction action {};
  action.sa_handler = exit_removing_temporaries;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

NewFileMode NewFileMode::of(const std::filesystem::path& made_from) {
  struct stat source {};
  if (::stat(made_from.c_str(), &source) != 0) return {};
  return {static_cast<unsigned>(source.st_mode) & 0777u};
}

NewFileMode NewFileMode::of_all(const std::vector<std::filesystem::path>& made_from) {
  NewFileMode mode;
  for (const std::filesystem::path& path : made_from) mode.bits &= of(path).bits;
  return mode;
}

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path, NewFileMode new_file_mode) : path_(std::move(path)) {
  if (path_.filename().empty() || path_.filename() == "." || path_.filename() == "..") {
    error_ = path_.string() + ": not a file name";
    return;
  }
  temp_ = temporary_path_for(path_);
  {
    const BlockInterrupts blocked;
    // The umask applies to the mode given here, as it does to cp's copies.
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                 static_cast<mode_t>(new_file_mode.bits & 0777u));
    if (fd_ >= 0) registry_slot_ = register_temporary(temp_);
  }
  if (fd_ < 0) {
    const int saved = errno;
    temp_.clear();
    fail("cannot create a temporary file next to it", saved);
    return;
  }
  // Keep the permissions of the file being replaced (only when it is a regular file of ours).
  struct stat target {};
  if (::stat(path_.c_str(), &target) == 0 && S_ISREG(target.st_mode)) {
    if (::fchmod(fd_, target.st_mode & 07777) != 0) fail("cannot keep its permissions", errno);
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (!committed_) abort();
}

void AtomicFileWriter::fail(std::string_view what, int error_number) {
  if (!error_.empty()) return;
  error_ = path_.string() + ": " + std::string(what) + ": " + std::strerror(error_number);
}

bool AtomicFileWriter::write(std::string_view bytes) {
  if (!ok()) return false;
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write", errno);
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

bool AtomicFileWriter::write_at(std::uint64_t offset, std::string_view bytes) {
  if (!ok()) return false;
  while (!bytes.empty()) {
    const ssize_t n = ::pwrite(fd_, bytes.data(), bytes.size(), static_cast<off_t>(offset));
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write", errno);
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
    offset += static_cast<std::uint64_t>(n);
  }
  return true;
}

std::optional<std::string> AtomicFileWriter::commit() {
  if (!ok()) {
    abort();
    return error_.empty() ? path_.string() + ": already written or abandoned" : error_;
  }
  if (::fsync(fd_) != 0) fail("cannot flush to disk", errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot close", errno);
  if (error_.empty() && ::rename(temp_.c_str(), path_.c_str()) != 0) fail("cannot replace", errno);
  if (!error_.empty()) {
    ::unlink(temp_.c_str());
    unregister_temporary(registry_slot_);
    temp_.clear();
    return error_;
  }
  // Renamed: a signal from here on unlinks a name that no longer exists, which is harmless.
  unregister_temporary(registry_slot_);
  committed_ = true;
  temp_.clear();
  // Make the rename itself durable.
  const int dir_fd = ::open(folder_of(path_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
  return std::nullopt;
}

void AtomicFileWriter::abort() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temp_.empty()) {
    ::unlink(temp_.c_str());
    unregister_temporary(registry_slot_);
    temp_.clear();
  }
}

std::optional<std::string> write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                                                 NewFileMode new_file_mode) {
  AtomicFileWriter writer(path, new_file_mode);
  writer.write(bytes);
  return writer.commit();
}

}  // namespace vimg
