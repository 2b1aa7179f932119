#pragma once
// Running vimg-force as a child process for the location study's tests: start it (stdin from
// /dev/null, output captured), wait for its end within a bound, watch its trial file grow.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/child_process.hpp"

namespace vimg::location_study_test {

namespace fs = std::filesystem;

inline const fs::path kForce = fs::path(VIMG_BINARY_DIR) / "apps" / "force" / "vimg-force";

inline std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Child {
  pid_t pid = -1;
  fs::path out, err;
};

struct Exit {
  int code = -1;
  std::string out, err;
  double seconds = 0.0;
};

// Starts vimg-force in `dir` with stdin from /dev/null (never a terminal), stdout and stderr captured in
// `dir` (the test's own folder, emptied at its start, so no earlier run's output is ever read).
inline Child spawn(const std::vector<std::string>& args, const fs::path& dir, const std::string& capture_name) {
  Child c;
  c.out = dir / (capture_name + ".stdout");
  c.err = dir / (capture_name + ".stderr");
  test::ChildSpec spec;
  spec.argv = {kForce.string()};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.dir = dir;
  spec.stdin_null = true;
  spec.stdout_file = c.out;
  spec.stderr_file = c.err;
  c.pid = test::spawn_child(spec);
  EXPECT_GT(c.pid, 0) << "fork failed: " << std::strerror(errno);
  return c;
}

// Waits for the program's end; one that is still running after two minutes is killed and reported
// as exit code -2, so a program that ignores its end fails the test instead of hanging it.
inline Exit wait_for(const Child& c, std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now()) {
  Exit e;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  pid_t ended = 0;
  while (c.pid > 0 && (ended = ::waitpid(c.pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (ended == c.pid) {
    e.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  } else if (ended == 0 && test::signal_child(c.pid, SIGKILL)) {
    test::reap_child(c.pid);
    e.code = -2;
  }
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  e.out = read_text(c.out);
  e.err = read_text(c.err);
  return e;
}

inline Exit run(const std::vector<std::string>& args, const fs::path& dir, const std::string& name = "run") {
  const auto start = std::chrono::steady_clock::now();
  return wait_for(spawn(args, dir, name), start);
}

// Complete rows in a trial file (lines after the header that end in a line break).
inline std::size_t complete_rows(const fs::path& csv) {
  const std::string text = read_text(csv);
  const auto lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  return lines == 0 ? 0 : lines - 1;
}

// Waits until the trial file holds `rows` complete rows: true, or false when the program ended first
// or a minute passed.
inline bool wait_for_rows(const Child& c, const fs::path& csv, std::size_t rows) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (c.pid > 0 && std::chrono::steady_clock::now() < give_up) {
    if (complete_rows(csv) >= rows) return true;
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(c.pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == c.pid) {
      return false;  // ended (left for wait_for to collect)
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

inline std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace vimg::location_study_test
