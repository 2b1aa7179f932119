#include "apps/force/force_args.hpp"

#include <cstdio>

#include "cmdline/command_line.hpp"

namespace vimg::force_app {

ForceArgsResult parse_force_args(int argc, const char* const* argv) {
  ForceArgs a;
  CLI::App app(
      "vimg-force: feel a volume scene with a force device. Runs the scene's haptic loop at the scene's rate "
      "(device rate) through the safety stack (start-up gate, soft wall, clamp, slew limit, stale-input and "
      "overrun watchdogs) until Ctrl-C, SIGTERM or --seconds.");
  cmdline::configure(app, "vimg-force");
  app.add_option("SCENE", a.scene_path, "a volume scene (.vscene.xml)")->required();
  app.add_flag("--allow-outside-files", a.allow_outside_files, "let the scene name data files outside its own folder (an absolute path, ..); off by default");
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
                              "without, it rests at the workspace centre");
  app.add_option("--seconds", a.seconds, "stop after S seconds (exit 0); without it, run until Ctrl-C or SIGTERM")
      ->check(cmdline::finite_in(0.001, 1e7));
  app.add_option("--log", a.log_file,
                 "write every cycle to this CSV (time_s,x_mm,y_mm,z_mm,fx_N,fy_N,fz_N,flags), atomically at the end");
  app.add_option("--telemetry", a.telemetry_file,
                 "write the run's figures (rate, jitter, overruns, max |F|, exit reason...) to this JSON file at the end");
  app.add_option("--realtime-priority", a.realtime_priority,
                 "SCHED_FIFO priority 1..99 of the haptic loop, 0 for none (needs CAP_SYS_NICE or an rtprio limit; "
                 "without, the loop runs at normal priority)")
      ->check(CLI::Range(0, 99));
  app.footer(
      "Exit status: 0 when --seconds has elapsed; 130 after SIGINT (Ctrl-C) and 143 after SIGTERM, in both cases only "
      "after the device has been sent zero force and the log and telemetry files are complete; 1 on a device fault "
      "or bad input (scene or path errors as FILE:LINE: error: ...); 2 on a usage error.\n");
  if (const auto code = cmdline::parse(app, argc, argv)) return {std::nullopt, *code};
  auto usage = [](const std::string& problem) {
    std::fprintf(stderr, "vimg-force: error: %s\nRun 'vimg-force --help' for usage.\n", problem.c_str());
    return ForceArgsResult{std::nullopt, cmdline::kExitUsage};
  };
  if (path->count() > 0 && !a.is_sim()) return usage("--path needs --device sim (a real device is moved by hand)");
  if (a.device.rfind("hid:", 0) == 0) a.hid_path = a.device.substr(4);
  return {a, cmdline::kExitOk};
}

}  // namespace vimg::force_app
