#include "apps/probe/probe_args.hpp"

#include "cmdline/command_line.hpp"

namespace vimg::probe {

ProbeArgsResult parse_probe_args(int argc, const char* const* argv) {
  ProbeArgs a;
  std::string move;
  CLI::App app(
      "vimg-probe: explore a volume scene. The window shows the slice y = const of the scene's first "
      "scalar data, the flow of its first vector data, the probe and the kinaesthetic force. Without "
      "--device the mouse moves the probe and the wheel moves the slice; with --device the scene's haptic "
      "loop runs on the force device and the window shows the probe and the force it sends, live.");
  cmdline::configure(app, "vimg-probe");
  app.add_option("SCENE", a.scene_path, "a volume scene (.vscene.xml)")->required();
  app.add_flag("--allow-outside-files", a.allow_outside_files, "let the scene name data files outside its own folder (an absolute path, ..); off by default");
  app.add_option("--device", a.device, "run the haptic loop on a force device: sim, hid or hid:/dev/hidrawN")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            if (v == "sim" || v == "hid" || (v.rfind("hid:", 0) == 0 && v.size() > 4)) return {};
            return "'" + v + "' is not sim, hid or hid:PATH";
          },
          "DEVICE"));
  auto* path = app.add_option("--path", a.path_file, "with --device sim: the hand follows this probe path CSV");
  app.add_option("--frames", a.frames, "draw N frames, then exit (scripted runs)")->check(CLI::Range(1, 1'000'000));
  app.add_option("--move", move, "with --frames, mouse mode: hold the probe at X_MM,Z_MM")->check(cmdline::point_2d());
  app.add_option("--screenshot", a.screenshot, "with --frames: save the last frame as a BMP");
  app.add_option("--realtime-priority", a.realtime_priority, "SCHED_FIFO priority 1..99 of the haptic loop, 0 for none")
      ->check(CLI::Range(0, 99));
  if (const auto code = cmdline::parse(app, argc, argv)) return {std::nullopt, *code};
  auto usage = [](const std::string& problem) {
    std::fprintf(stderr, "vimg-probe: error: %s\nRun 'vimg-probe --help' for usage.\n", problem.c_str());
    return ProbeArgsResult{std::nullopt, cmdline::kExitUsage};
  };
  if (path->count() > 0 && a.device != "sim") return usage("--path needs --device sim");
  if (!move.empty()) {
    if (!a.device.empty()) return usage("--move is for mouse mode; with --device the device moves the probe");
    double x = 0.0, z = 0.0;
    cmdline::parse_point_2d(move, x, z);
    a.move_mm = std::make_pair(x, z);
  }
  if ((a.move_mm || !a.screenshot.empty()) && a.frames == 0) return usage("--move and --screenshot need --frames N");
  return {a, cmdline::kExitOk};
}

}  // namespace vimg::probe
