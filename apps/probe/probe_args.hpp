#pragma once
// The command line of vimg-probe (`vimg-probe --help` lists it), parsed with the project's
// conventions (cmdline/command_line.hpp).
#include <optional>
#include <string>

namespace vimg::probe {

struct ProbeArgs {
  std::string scene_path;
  int frames = 0;         // > 0: draw this many frames, then exit (scripted runs); 0: until closed
  std::optional<std::pair<double, double>> move_mm;  // scripted mouse position x, z
  std::string screenshot;  // BMP of the last frame (with --frames)
};

struct ProbeArgsResult {
  std::optional<ProbeArgs> args;
  int exit_code = 0;  // when args is empty: 0 (help, version) or 2 (usage error), already printed
};

ProbeArgsResult parse_probe_args(int argc, const char* const* argv);

}  // namespace vimg::probe
