#pragma once
// `vimg serve` as a user runs it: a child process with --port 0 whose printed URL is read from its
// stdout (the test waits for that line, it never sleeps). The page's files come from a folder of
// stand-ins (VIMG_WEB_ASSETS), so that no Emscripten build is needed; TMPDIR is the test's own
// folder, so that the temporary site can be looked at.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/child_process.hpp"
#include "tests/net/raw_http.hpp"
#include "web/site_builder/web_site.hpp"

namespace vimg::test {

inline const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";

// The page's files and the study pages (web/site_builder/web_site.hpp names them): stand-ins in `dir`.
inline void write_stand_in_assets(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (const char* name : kWebAssetFiles) std::ofstream(dir / name) << "stand-in " << name << "\n";
  for (const char* name : kStudyAssetFiles) std::ofstream(dir / name) << "stand-in " << name << "\n";
}

// The child process itself: `vimg serve ARGS... --port 0` with VIMG_WEB_ASSETS=assets and
// TMPDIR=tmp, its stdout and stderr on the given descriptors (-1 leaves that one inherited; the
// child closes nothing else of the test's, every descriptor here is opened close-on-exec). Killed
// and reaped when it goes out of scope, unless stop_with() did that. A `wrapper` (a program and
// its arguments: strace, prlimit) runs vimg serve in its stead.
class ServeChild {
 public:
  ServeChild(const std::vector<std::string>& args, const std::filesystem::path& assets, const std::filesystem::path& tmp,
             int stdout_fd, int stderr_fd = -1, const std::vector<std::string>& wrapper = {}) {
    ChildSpec spec;
    spec.argv = wrapper;
    spec.argv.insert(spec.argv.end(), {kVimg, "serve"});
    spec.argv.insert(spec.argv.end(), args.begin(), args.end());
    spec.argv.insert(spec.argv.end(), {"--port", "0"});
    spec.env = {{"VIMG_WEB_ASSETS", assets.string()}, {"TMPDIR", tmp.string()}};
    spec.stdout_fd = stdout_fd;
    spec.stderr_fd = stderr_fd;
    pid_ = spawn_child(spec);
    EXPECT_GT(pid_, 0) << "fork failed: " << std::strerror(errno);
  }
  ~ServeChild() {
    if (!reaped_ && signal_child(pid_, SIGKILL)) reap_child(pid_);
  }
  ServeChild(const ServeChild&) = delete;
  ServeChild& operator=(const ServeChild&) = delete;

  pid_t pid() const { return pid_; }

  // Whether the child has ended (it stays unreaped, for stop_with() or the destructor); a child
  // that was never started has.
  bool ended() const {
    if (pid_ <= 0) return true;
    siginfo_t info{};
    return waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid_;
  }

  // Waits for the child to end by itself; its exit status (-1 if a signal killed it, or it never started).
  int wait_for_exit() {
    if (pid_ <= 0 || reaped_) return -1;
    const int status = reap_child(pid_);
    reaped_ = true;
    return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  // Sends the signal and returns the exit status (-1 if a signal killed it, or it never started).
  int stop_with(int signal_number) {
    if (pid_ <= 0 || reaped_) return -1;
    signal_child(pid_, signal_number);
    const int status = reap_child(pid_);
    reaped_ = true;
    return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
};

// The server with its stdout on a pipe that wait_for_port() reads.
class ServeProcess {
 public:
  ServeProcess(const std::vector<std::string>& args, const std::filesystem::path& assets, const std::filesystem::path& tmp,
               const std::vector<std::string>& wrapper = {})
      : pipe_(make_pipe()), child_(args, assets, tmp, pipe_.write, -1, wrapper) {
    close(pipe_.write);
  }
  ~ServeProcess() {
    if (pipe_.read >= 0) close(pipe_.read);
  }
  ServeProcess(const ServeProcess&) = delete;
  ServeProcess& operator=(const ServeProcess&) = delete;

  // Reads stdout until the line with the URL (`scheme` "http" or "https"); its port, or 0 if the
  // process ended first or printed no URL within kHangBound (a hang: printed() shows how far it got).
  int wait_for_port(const std::string& scheme = "http") {
    const std::string prefix = scheme + "://127.0.0.1:";
    const auto give_up = std::chrono::steady_clock::now() + kHangBound;
    while (true) {
      const std::size_t at = out_.find(prefix);
      if (at != std::string::npos && out_.find('/', at + prefix.size()) != std::string::npos) {
        return std::stoi(out_.substr(at + prefix.size()));
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - std::chrono::steady_clock::now());
      pollfd readable{pipe_.read, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&readable, 1, static_cast<int>(left.count())) == 0) return 0;
      char buffer[1024];
      const ssize_t n = read(pipe_.read, buffer, sizeof buffer);
      if (n <= 0) return 0;
      out_.append(buffer, static_cast<std::size_t>(n));
    }
  }
  const std::string& printed() const { return out_; }

  int stop_with(int signal_number) { return child_.stop_with(signal_number); }
  ServeChild& child() { return child_; }

 private:
  struct Pipe {
    int read = -1;
    int write = -1;
  };
  static Pipe make_pipe() {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) return {};
    return {fds[0], fds[1]};
  }
  Pipe pipe_;
  ServeChild child_;
  std::string out_;
};

}  // namespace vimg::test
