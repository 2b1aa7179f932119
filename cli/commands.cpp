#include "cli/command.hpp"

#include <array>

namespace vimg::cli {

// Each command's entry point, defined in its own cli/cmd_*.cpp.

std::span<const Command> all_commands() {
  static const std::array<Command, 0> commands{};
  return commands;
}

}  // namespace vimg::cli
