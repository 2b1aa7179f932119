// `vimg`: the headless command. Dispatches to the subcommands listed in cli/commands.cpp.
#include <cstdio>
#include <string_view>
#include <vector>

#include "cli/command.hpp"

namespace {

void print_help(std::FILE* out) {
  std::fprintf(out, "usage: vimg COMMAND [ARGS...]\n\ncommands:\n");
  for (const auto& c : vimg::cli::all_commands()) {
    std::fprintf(out, "  %-60.*s %.*s\n", static_cast<int>(c.usage.size()), c.usage.data(),
                 static_cast<int>(c.summary.size()), c.summary.data());
  }
  std::fprintf(out, "\n  vimg --version\n  vimg --help\n");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace vimg::cli;
  if (argc < 2) {
    print_help(stderr);
    return kExitUsage;
  }
  const std::string_view name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_help(stdout);
    return kExitOk;
  }
  if (name == "--version") {
    std::printf("vimg %s\n", VIMG_VERSION);
    return kExitOk;
  }
  std::vector<std::string_view> args(argv + 2, argv + argc);
  for (const auto& c : all_commands()) {
    if (c.name == name) return c.run(args);
  }
  std::fprintf(stderr, "vimg: unknown command '%s'\n", argv[1]);
  print_help(stderr);
  return kExitUsage;
}
