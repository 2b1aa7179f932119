#pragma once
// One `vimg` subcommand. Each lives in its own cli/cmd_*.cpp and is listed in cli/commands.cpp.
#include <span>
#include <string_view>

namespace vimg::cli {

// Exit codes shared by every command (spec section 4).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

struct Command {
  std::string_view name;     // e.g. "validate"
  std::string_view usage;    // e.g. "vimg validate FILE..."
  std::string_view summary;  // one line for `vimg --help`
  int (*run)(std::span<const std::string_view> args);  // args after the command name
};

std::span<const Command> all_commands();

}  // namespace vimg::cli
