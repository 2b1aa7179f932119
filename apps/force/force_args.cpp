#include "apps/force/force_args.hpp"

#include <cstdio>

#include "cmdline/command_line.hpp"
#include "storage/diagnostic.hpp"
#include "storage/number_text.hpp"
#include "storage/study/trial_log.hpp"

namespace vimg::force_app {

ForceArgsResult parse_force_args(int argc, const char* const* argv) {
  ForceArgs a;
  CLI::App app(
      "vimg-force: feel a volume scene with a force device. Runs the scene's haptic loop at the scene's rate "
      "(device rate) through the safety stack (start-up gate, soft wall, clamp, slew limit, stale-input and "
      "overrun watchdogs) until Ctrl-C, SIGTERM or --seconds. With --study instead of a scene, runs the volume "
      "paper's location study for one participant (docs/volume-location-study.md, \"Location study\").");
  cmdline::configure(app, "vimg-force");
  auto* scene = app.add_option("SCENE", a.scene_path, "a volume scene (.vscene.xml); not with --study");
  auto* outside = app.add_flag("--allow-outside-files", a.allow_outside_files,
                               "let the scene name data files outside its own folder (an absolute path, ..); off by default");
  app.add_option("--device", a.device,
                 "sim: the simulated device; hid: the first HID device that answers the force protocol; "
                 "hid:PATH: that hidraw device (e.g. hid:/dev/hidraw3)")
      ->required()
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            if (v == "sim" || v == "hid" || (v.rfind("hid:", 0) == 0 && v.size() > 4)) return {};
            return "'" + v + "' is not sim, hid or hid:PATH";
          },
          "DEVICE"));
  auto* path = app.add_option("--path", a.path_file,
                              "with --device sim: the hand follows this probe path CSV (time_s,x_mm,y_mm,z_mm); "
                              "without, it rests at the workspace centre. In a study it starts again in every trial");
  auto* seconds = app.add_option("--seconds", a.seconds, "stop after S seconds (exit 0); without it, run until Ctrl-C or SIGTERM")
                      ->check(cmdline::finite_in(0.001, 1e7));
  auto* log = app.add_option("--log", a.log_file,
                             "write every cycle to this CSV (time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,flags), atomically at the end");
  auto* telemetry = app.add_option(
      "--telemetry", a.telemetry_file,
      "write the run's figures (rate, jitter, overruns, max |F|, exit reason...) to this JSON file at the end");
  app.add_option("--realtime-priority", a.realtime_priority,
                 "SCHED_FIFO priority 1..99 of the haptic loop, 0 for none (needs CAP_SYS_NICE or an rtprio limit; "
                 "without, the loop runs at normal priority)")
      ->check(CLI::Range(0, 99));
  auto* study = app.add_option("--study", a.study_file,
                               "run this location study (<locationStudy>, docs/format-studies.md) instead of a scene: one trial after "
                               "another, each a new data set; button 0 (or Enter on the terminal) marks");
  auto* participant =
      app.add_option("--participant", a.participant, "with --study: the participant's ID ([A-Za-z0-9_-], 1 to 64 characters)");
  auto* results = app.add_option("--results", a.results_dir,
                                 "with --study: the folder of the trial files; the trials go to DIR/ID.location.csv, one "
                                 "synced row per trial, and a new run of the same participant continues after the last row");
  auto* restart = app.add_flag("--restart", a.restart,
                               "with --study: a participant who has finished every trial starts again (the old file is kept "
                               "aside as DIR/ID.location.<UTC stamp>.csv)");
  auto* marks = app.add_option("--marks", a.marks_file,
                               "with --study and --device sim: the simulated participant presses button 0 at these times "
                               "(CSV trial,time_s: seconds after the trial's start, one row per trial)");
  std::string sim_fault;
  auto* fault = app.add_option("--sim-fault", sim_fault,
                               "with --study and --device sim, to try the redo of a trial: a read of the simulated device "
                               "fails " + format_decimal(kSimFaultTime_s) + " s into each of trial TRIAL's first COUNT attempts")
                    ->type_name("TRIAL:COUNT")
                    ->check(CLI::Validator(
                        [](std::string& v) -> std::string {
                          const std::size_t colon = v.find(':');
                          const auto whole = [](const std::string& t) {
                            return !t.empty() && t.size() <= 6 && t.find_first_not_of("0123456789") == std::string::npos &&
                                   std::stoul(t) > 0;
                          };
                          if (colon != std::string::npos && whole(v.substr(0, colon)) && whole(v.substr(colon + 1))) return {};
                          return "'" + v + "' is not TRIAL:COUNT (two whole numbers from 1)";
                        },
                        "TRIAL:COUNT"));
  app.footer(
      "Exit status: 0 when --seconds has elapsed or the study is complete; 130 after SIGINT (Ctrl-C) and 143 after "
      "SIGTERM, in both cases only after the device has been sent zero force and the log and telemetry files are "
      "complete (in a study: every finished trial is in the trial file, the trial under way is not); 1 on a device "
      "fault or bad input (scene, path, study or marks errors as FILE:LINE: error: ...); 2 on a usage error.\n");
  if (const auto code = cmdline::parse(app, argc, argv)) return {std::nullopt, *code};
  auto usage = [](const std::string& problem) {
    std::fprintf(stderr, "vimg-force: error: %s\nRun 'vimg-force --help' for usage.\n", problem.c_str());
    return ForceArgsResult{std::nullopt, cmdline::kExitUsage};
  };
  if (path->count() > 0 && !a.is_sim()) return usage("--path needs --device sim (a real device is moved by hand)");
  if (marks->count() > 0 && !a.is_sim()) return usage("--marks needs --device sim (a participant presses a real button)");
  if (fault->count() > 0 && !a.is_sim()) return usage("--sim-fault needs --device sim");
  if (fault->count() > 0) {
    a.sim_fault_trial = std::stoul(sim_fault.substr(0, sim_fault.find(':')));
    a.sim_fault_count = std::stoi(sim_fault.substr(sim_fault.find(':') + 1));
  }
  if (study->count() > 0) {
    if (scene->count() > 0) return usage("give a SCENE or --study, not both (a study makes its own scenes)");
    for (const auto* o : {outside, seconds, log, telemetry}) {
      if (o->count() > 0) return usage(o->get_name() + " is for a scene, not for --study");
    }
    if (participant->count() == 0) return usage("--study needs --participant ID");
    if (results->count() == 0) return usage("--study needs --results DIR");
    if (!valid_participant_id(a.participant)) {
      return usage("--participant '" + escape_input(a.participant) + "' is not an ID: 1 to 64 of A-Z, a-z, 0-9, '_' and '-' (it names files)");
    }
  } else {
    if (scene->count() == 0) return usage("SCENE or --study is required");
    for (const auto* o : {participant, results, restart, marks, fault}) {
      if (o->count() > 0) return usage(o->get_name() + " needs --study");
    }
  }
  if (a.device.rfind("hid:", 0) == 0) a.hid_path = a.device.substr(4);
  return {a, cmdline::kExitOk};
}

}  // namespace vimg::force_app
