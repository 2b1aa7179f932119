#pragma once
// The exit codes every program of the project uses (docs/format-command.md, the command contract):
//   0    success, and --help / --version
//   1    bad input (a file that does not read, with FILE:LINE: error: ...)
//   2    a usage error
//   130  interrupted by SIGINT, 143 by SIGTERM (the actuator at rest, no half-written file)
// Apart from command_line.hpp so that code which only ends a program does not parse CLI11.

namespace vimg::cmdline {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitSigint = 130;
inline constexpr int kExitSigterm = 143;

}  // namespace vimg::cmdline
