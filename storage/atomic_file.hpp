#pragma once
// The one way the project writes a file (spec section 4): readers see either the old content or
// the complete new one, never a torn file, and nobody else's file is ever touched.
//   1. a temporary file is created next to the target with O_CREAT|O_EXCL|O_NOFOLLOW (a planted
//      file or symlink of that name makes the create fail; it is never followed or reused);
//   2. it takes the target's permission bits when the target exists (a 0600 file stays 0600);
//      a new file gets 0666 less the umask, or, when it is made from another file (a convert, an
//      import, a render), that file's read, write and execute bits less the umask, as cp gives a
//      copy (NewFileMode::of: a private 0600 input never becomes a 0644 output);
//   3. the bytes are written (at once, or streamed by AtomicFileWriter), fsync'ed, the file is
//      renamed over the target, and the folder is fsync'ed so that the rename is durable;
//   4. on any error, and when a writer is destroyed without commit(), the temporary is removed;
//   5. while it exists, the temporary's path sits in a process-wide registry that a signal handler
//      can empty (remove_pending_temporaries), so that SIGINT/SIGTERM leave no temporary behind.
//
// Threads: an AtomicFileWriter belongs to one thread at a time; it may block on the disk, so it
// never runs on a real-time thread (feed it through an SPSC ring from there).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vimg {

// At most this many temporaries are registered at once (a program writes one or two at a time);
// a writer beyond them still works, but a signal would leave its temporary behind.
inline constexpr int kMaxPendingTemporaries = 32;

// Removes (unlink) every temporary that a writer of this process has created and neither committed
// nor removed yet. Async-signal-safe and lock-free: for signal handlers. The writers themselves
// are left as they are (their later calls fail), so call it only on the way out.
void remove_pending_temporaries() noexcept;

// Installs handlers for SIGINT and SIGTERM that remove the pending temporaries and end the process
// at once with 130 or 143 (_exit). For programs whose only duty on a signal is to leave no
// half-written file (vimg). A program that must do more (bring an actuator to rest) keeps its own
// handler and calls remove_pending_temporaries() from it, or finishes its writers itself.
void exit_on_interrupt_removing_temporaries();

// The permission bits a new file is created with (the umask still applies; a target that exists
// keeps its own bits whatever this says).
struct NewFileMode {
  unsigned bits = 0666;
  // The read, write and execute bits of the file an output is made from (no set-user-ID, set-group-ID
  // or sticky bit, as cp without -p); 0666 when it cannot be read.
  static NewFileMode of(const std::filesystem::path& made_from);
  // An output made from several files (a report of many participants' trial files, a comparison of
  // many images): the bits every one of them has, so that one private input keeps the output private.
  static NewFileMode of_all(const std::vector<std::filesystem::path>& made_from);
};

// Returns an error message naming the path, or nothing on success.
std::optional<std::string> write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                                                 NewFileMode new_file_mode = {});

class AtomicFileWriter {
 public:
  // Creates the temporary file. On failure, error() says why and every other call fails.
  explicit AtomicFileWriter(std::filesystem::path path, NewFileMode new_file_mode = {});
  ~AtomicFileWriter();  // removes the temporary unless committed
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  bool ok() const { return fd_ >= 0 && error_.empty(); }
  // The first error, naming the target path; empty while all is well.
  const std::string& error() const { return error_; }
  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& temporary_path() const { return temp_; }

  // Appends bytes. False (and error() set) on failure; later calls then fail too.
  bool write(std::string_view bytes);
  // Overwrites bytes already written, at `offset` from the start (e.g. sizes in a header).
  bool write_at(std::uint64_t offset, std::string_view bytes);
  // fsync, rename over the target, fsync the folder. Returns the error message, or nothing.
  std::optional<std::string> commit();
  // Removes the temporary file; the target is left as it was.
  void abort() noexcept;

 private:
  void fail(std::string_view what, int error_number);

  std::filesystem::path path_;
  std::filesystem::path temp_;
  int registry_slot_ = -1;  // this temporary's place in the registry, -1 when not registered
  int fd_ = -1;
  bool committed_ = false;
  std::string error_;
};

}  // namespace vimg
