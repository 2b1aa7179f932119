#pragma once
// A program started by a test as a child process, safely. Everything the child needs (its argv,
// its environment, the paths of the files it writes) is made before fork(); between fork() and
// execve() the child calls only async-signal-safe functions (no allocation, no setenv: the test
// process may have threads, and another thread may hold the allocator's lock at the fork). A fork
// that fails gives pid -1, which is never signalled: kill(-1, ...) would reach every process of
// the user, the test runner included.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

extern char** environ;

namespace vimg::test {

struct ChildSpec {
  std::vector<std::string> argv;  // argv[0] is the program's path
  std::vector<std::pair<std::string, std::string>> env;  // set in the child's environment (others inherited)
  std::filesystem::path dir;      // the child's working folder; empty: the test's
  bool stdin_null = false;        // stdin from /dev/null instead of the test's
  std::filesystem::path stdout_file, stderr_file;  // truncated and written; empty: see the descriptors
  int stdout_fd = -1, stderr_fd = -1;              // -1 (and no file): inherited
};

// Starts the child; its pid (> 0), or -1 when fork() failed. The child exits 126 when its folder
// or a file cannot be opened, 127 when the program cannot be run.
inline pid_t spawn_child(const ChildSpec& spec) {
  if (spec.argv.empty()) return -1;
  std::vector<std::string> argv_text = spec.argv;
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_text;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const auto& [name, value] : spec.env) replaced = replaced || entry.compare(0, name.size() + 1, name + "=") == 0;
    if (!replaced) env_text.push_back(entry);
  }
  for (const auto& [name, value] : spec.env) env_text.push_back(name + "=" + value);
  std::vector<char*> envp;
  for (std::string& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string dir = spec.dir.string(), out = spec.stdout_file.string(), err = spec.stderr_file.string();

  const pid_t pid = ::fork();
  if (pid != 0) return pid < 0 ? -1 : pid;
  // The child: async-signal-safe calls only, up to execve.
  sigset_t none;
  sigemptyset(&none);
  sigprocmask(SIG_SETMASK, &none, nullptr);
  if (!dir.empty() && ::chdir(dir.c_str()) != 0) _exit(126);
  if (spec.stdin_null) {
    const int in = ::open("/dev/null", O_RDONLY);
    if (in < 0 || ::dup2(in, STDIN_FILENO) < 0) _exit(126);
  }
  const auto redirect = [](const std::string& file, int fd, int target) {
    if (!file.empty()) fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    else if (fd < 0) return true;
    return fd >= 0 && ::dup2(fd, target) >= 0;
  };
  if (!redirect(out, spec.stdout_fd, STDOUT_FILENO) || !redirect(err, spec.stderr_fd, STDERR_FILENO)) _exit(126);
  ::execve(argv[0], argv.data(), envp.data());
  _exit(127);
}

// Sends the signal to a started child; a pid that is not one (<= 0) is never signalled. Whether
// the signal was sent.
inline bool signal_child(pid_t pid, int signal_number) { return pid > 0 && ::kill(pid, signal_number) == 0; }

// Waits for the child's end; its wait status, or -1 for a pid that is not one.
inline int reap_child(pid_t pid) {
  if (pid <= 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return status;
}

}  // namespace vimg::test
