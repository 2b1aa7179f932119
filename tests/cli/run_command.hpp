#pragma once
// Runs a shell command line as a user would and keeps what it printed (stdout and stderr
// together) and its exit status.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace vimg::test {

struct CommandRun {
  int exit_code = -1;  // -1: it did not exit normally (a signal)
  std::string out;
};

inline CommandRun run_command(const std::string& command_line) {
  CommandRun run;
  FILE* pipe = ::popen((command_line + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace vimg::test
