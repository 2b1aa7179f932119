#include "apps/probe/probe_args.hpp"

#include "cmdline/command_line.hpp"

namespace vimg::probe {

ProbeArgsResult parse_probe_args(int argc, const char* const* argv) {
  ProbeArgs a;
  std::string move;
  CLI::App app(
      "vimg-probe: explore a volume scene. The window shows the slice y = const of the scene's first "
      "scalar data, the flow of its first vector data, the probe and the kinaesthetic force. The mouse "
      "moves the probe and the wheel moves the slice.");
  cmdline::configure(app, "vimg-probe");
  app.add_option("SCENE", a.scene_path, "a volume scene (.vscene.xml)")->required();
  app.add_option("--frames", a.frames, "draw N frames, then exit (scripted runs)")->check(CLI::Range(1, 1'000'000));
  app.add_option("--move", move, "with --frames: hold the probe at X_MM,Z_MM")->check(cmdline::point_2d());
  app.add_option("--screenshot", a.screenshot, "with --frames: save the last frame as a BMP");
  if (const auto code = cmdline::parse(app, argc, argv)) return {std::nullopt, *code};
  auto usage = [](const std::string& problem) {
    std::fprintf(stderr, "vimg-probe: error: %s\nRun 'vimg-probe --help' for usage.\n", problem.c_str());
    return ProbeArgsResult{std::nullopt, cmdline::kExitUsage};
  };
  if (!move.empty()) {
    double x = 0.0, z = 0.0;
    cmdline::parse_point_2d(move, x, z);
    a.move_mm = std::make_pair(x, z);
  }
  if ((a.move_mm || !a.screenshot.empty()) && a.frames == 0) return usage("--move and --screenshot need --frames N");
  return {a, cmdline::kExitOk};
}

}  // namespace vimg::probe
