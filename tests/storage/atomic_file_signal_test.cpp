// SIGINT/SIGTERM while a file is being written (docs/limits.md, issue 13 "one way to write a
// file"): the handler of exit_on_interrupt_removing_temporaries() removes every temporary of the
// process's AtomicFileWriters and exits 130/143; the target keeps its old content.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "storage/atomic_file.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

// A child that opens `writers` writers in `dir` (written, not committed), tells the parent through
// the pipe, and waits for the signal. Returns the child's wait status.
int status_of_child_signalled(const fs::path& dir, int writers, int signal_number) {
  int ready[2];
  if (::pipe(ready) != 0) return -1;
  const pid_t pid = ::fork();
  if (pid < 0) {  // never signalled: kill(-1, ...) would reach every process of the user
    ADD_FAILURE() << "fork failed";
    ::close(ready[0]);
    ::close(ready[1]);
    return -1;
  }
  if (pid == 0) {
    ::close(ready[0]);
    exit_on_interrupt_removing_temporaries();
    std::vector<AtomicFileWriter*> open;
    for (int i = 0; i < writers; ++i) {
      auto* w = new AtomicFileWriter(dir / ("out" + std::to_string(i) + ".vimg"));
      w->write("half of a file");
      open.push_back(w);
    }
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
    for (;;) ::pause();
  }
  ::close(ready[1]);
  char byte = 0;
  const bool ready_read = ::read(ready[0], &byte, 1) == 1;
  ::close(ready[0]);
  EXPECT_TRUE(ready_read);
  EXPECT_EQ(names_in(dir).size(), static_cast<std::size_t>(writers) + 1) << "the old target and the temporaries";
  ::kill(pid, signal_number);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(AtomicFileSignal, SigintAndSigtermRemoveEveryPendingTemporaryAndExit130Or143) {
  for (const auto& [signal_number, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}}) {
    const fs::path dir = fresh_dir("atomic_file_signal_" + std::to_string(signal_number));
    {
      std::ofstream(dir / "out0.vimg") << "old content";
    }
    const int status = status_of_child_signalled(dir, 3, signal_number);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal_number;
    EXPECT_EQ(WEXITSTATUS(status), code);
    EXPECT_EQ(names_in(dir), std::vector<std::string>{"out0.vimg"}) << "only the old target is left";
    std::ifstream in(dir / "out0.vimg");
    std::string content;
    std::getline(in, content);
    EXPECT_EQ(content, "old content");
  }
}

TEST(AtomicFileSignal, CommittedAndAbortedWritersLeaveTheRegistry) {
  const fs::path dir = fresh_dir("atomic_file_registry");
  // More writers over time than the registry has slots: each one frees its slot when done.
  for (int i = 0; i < 3 * kMaxPendingTemporaries; ++i) {
    AtomicFileWriter w(dir / ("f" + std::to_string(i % 4)));
    ASSERT_TRUE(w.write("x"));
    if (i % 2 == 0) {
      ASSERT_FALSE(w.commit().has_value());
    }
  }
  // A committed file is never touched by the handler's removal.
  remove_pending_temporaries();
  EXPECT_EQ(names_in(dir).size(), 2u) << "f0 and f2 committed, nothing pending";
  // A pending one is registered and removed.
  AtomicFileWriter pending(dir / "p");
  ASSERT_TRUE(pending.write("x"));
  ASSERT_TRUE(fs::exists(pending.temporary_path()));
  remove_pending_temporaries();
  EXPECT_FALSE(fs::exists(pending.temporary_path()));
}

}  // namespace
}  // namespace vimg
