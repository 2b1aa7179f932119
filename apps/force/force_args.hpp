#pragma once
// The command line of vimg-force (`vimg-force --help` lists it), parsed with the project's
// conventions (cmdline/command_line.hpp): --help and --version exit 0, usage errors exit 2.
#include <optional>
#include <string>

namespace vimg::force_app {

struct ForceArgs {
  std::string scene_path;
  bool allow_outside_files = false;  // --allow-outside-files: data files may leave the scene's folder
  std::string device;      // "sim", "hid" or "hid:PATH"
  std::string hid_path;    // PATH of "hid:PATH" ("" for "hid": search)
  std::string path_file;   // sim only: the hand follows this probe path (time_s,x_mm,y_mm,z_mm)
  std::optional<double> seconds;  // run this long, then stop (exit 0); without: until a signal
  std::string log_file;        // the per-cycle CSV log
  std::string telemetry_file;  // the run's JSON summary
  int realtime_priority = 80;  // SCHED_FIFO for the loop thread; 0: normal scheduling
  bool is_sim() const { return device == "sim"; }
};

struct ForceArgsResult {
  std::optional<ForceArgs> args;
  int exit_code = 0;  // when args is empty: 0 (help, version) or 2 (usage error), already printed
};

ForceArgsResult parse_force_args(int argc, const char* const* argv);

}  // namespace vimg::force_app
