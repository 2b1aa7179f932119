// Runs a piece of work in a forked child under an address-space cap (RLIMIT_AS) and a CPU-time cap
// (RLIMIT_CPU), and reports how it ended. Hostile-input tests use it to hold an importer to "within
// seconds and a few hundred MiB, or refused with its limit named" without timing anything: a child
// that exceeds the CPU cap is killed by SIGXCPU/SIGKILL, one that exceeds the memory cap fails to
// allocate (std::bad_alloc, or a crash), and either shows in ChildOutcome.
//
// Sanitizer builds reserve terabytes of shadow memory, so there the memory cap is not applied
// (memory_capped is false) and only the CPU cap holds; the CPU cap is multiplied by 10 there.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <functional>
#include <new>
#include <string>

namespace vimg::test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif
#else
inline constexpr bool kUnderSanitizer = false;
#endif

struct ChildOutcome {
  bool exited = false;      // the child returned normally (exit_code holds its status)
  int exit_code = -1;       // 0: fn returned; 3: std::bad_alloc; 4: another exception
  int signal = 0;           // the signal that ended the child, if it did not exit
  std::string output;       // what fn returned (or the exception's text)
  bool memory_capped = false;

  bool finished() const { return exited && exit_code == 0; }
  std::string describe() const {
    if (exited) return "exit " + std::to_string(exit_code) + ": " + output;
    return "killed by signal " + std::to_string(signal) + " (" + output + ")";
  }
};

inline ChildOutcome run_bounded(const std::function<std::string()>& fn, std::size_t address_space_bytes,
                                int cpu_seconds) {
  ChildOutcome outcome;
  outcome.memory_capped = !kUnderSanitizer;
  int fds[2];
  if (pipe(fds) != 0) {
    outcome.output = "pipe failed";
    return outcome;
  }
  const pid_t pid = fork();
  if (pid < 0) {
    outcome.output = "fork failed";
    close(fds[0]);
    close(fds[1]);
    return outcome;
  }
  if (pid == 0) {
    close(fds[0]);
    const rlim_t cpu = static_cast<rlim_t>(kUnderSanitizer ? cpu_seconds * 10 : cpu_seconds);
    const rlimit cpu_limit{cpu, cpu + 1};
    setrlimit(RLIMIT_CPU, &cpu_limit);
    if (!kUnderSanitizer) {
      const rlimit as_limit{static_cast<rlim_t>(address_space_bytes), static_cast<rlim_t>(address_space_bytes)};
      setrlimit(RLIMIT_AS, &as_limit);
    }
    int code = 0;
    std::string text;
    try {
      text = fn();
    } catch (const std::bad_alloc&) {
      code = 3;
      text = "out of memory (std::bad_alloc)";
    } catch (const std::exception& e) {
      code = 4;
      text = e.what();
    }
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    close(fds[1]);
    _exit(code);
  }
  close(fds[1]);
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    outcome.output.append(buffer, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) {
    outcome.exited = true;
    outcome.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    outcome.signal = WTERMSIG(status);
  }
  return outcome;
}

}  // namespace vimg::test
