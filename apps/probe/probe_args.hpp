#pragma once
// The command line of vimg-probe (`vimg-probe --help` lists it), parsed with the project's
// conventions (cmdline/command_line.hpp).
#include <optional>
#include <string>

namespace vimg::probe {

struct ProbeArgs {
  std::string scene_path;
  bool allow_outside_files = false;  // --allow-outside-files
  // Mouse mode (no --device): the mouse moves the probe in the slice.
  // Device mode: the scene's haptic loop runs on a force device and the window shows it live.
  std::string device;     // "", "sim", "hid" or "hid:PATH"
  std::string path_file;  // sim only: the scripted hand path (time_s,x_mm,y_mm,z_mm)
  int frames = 0;         // > 0: draw this many frames, then exit (scripted runs); 0: until closed
  std::optional<std::pair<double, double>> move_mm;  // scripted mouse position x, z
  std::string screenshot;  // BMP of the last frame (with --frames)
  int realtime_priority = 80;
};

struct ProbeArgsResult {
  std::optional<ProbeArgs> args;
  int exit_code = 0;  // when args is empty: 0 (help, version) or 2 (usage error), already printed
};

ProbeArgsResult parse_probe_args(int argc, const char* const* argv);

}  // namespace vimg::probe
