#pragma once
// The command line of vimg-force (`vimg-force --help` lists it), parsed with the project's
// conventions (cmdline/command_line.hpp): --help and --version exit 0, usage errors exit 2.
// Two ways to run it:
//   vimg-force SCENE --device ...                       a scene's haptic loop (force_session.hpp)
//   vimg-force --study LSTUDY.xml --participant ID --results DIR --device ...
//                                                       the volume paper's location study
//                                                       (location_study.hpp)
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
  // The location study (study_file set: the program runs the study instead of a scene).
  std::string study_file;   // --study LSTUDY.xml
  std::string participant;  // --participant ID ([A-Za-z0-9_-]{1,64})
  std::string results_dir;  // --results DIR: DIR/ID.location.csv
  bool restart = false;     // --restart: a finished participant's file is kept aside, the study begins again
  std::string marks_file;   // sim only: per trial, when the simulated participant presses button 0 (trial,time_s)
  // sim only, for tests of the redo (--sim-fault TRIAL:COUNT): a read of the simulated device fails
  // kSimFaultTime_s into each of trial sim_fault_trial's first sim_fault_count attempts (0: none).
  std::size_t sim_fault_trial = 0;
  int sim_fault_count = 0;
  bool is_sim() const { return device == "sim"; }
  bool is_study() const { return !study_file.empty(); }
};

// When an injected fault (--sim-fault) comes in a trial: on the trial's own clock, before any mark a
// test scripts.
inline constexpr double kSimFaultTime_s = 0.1;

struct ForceArgsResult {
  std::optional<ForceArgs> args;
  int exit_code = 0;  // when args is empty: 0 (help, version) or 2 (usage error), already printed
};

ForceArgsResult parse_force_args(int argc, const char* const* argv);

}  // namespace vimg::force_app
