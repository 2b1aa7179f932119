#include "apps/vimg-player/player_args.hpp"

#include <charconv>
#include <cstdio>

#include "cmdline/command_line.hpp"

namespace vimg::player_app {
namespace {

bool parse_window(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string::npos) return false;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto w = std::from_chars(begin, begin + x, width);
  const auto h = std::from_chars(begin + x + 1, end, height);
  return w.ec == std::errc() && w.ptr == begin + x && h.ec == std::errc() && h.ptr == end && width >= 64 && height >= 64;
}

}  // namespace

ArgsResult parse_player_args(const std::vector<std::string>& arguments) {
  PlayerArgs a;
  double px_per_mm = 0.0;
  std::string window, actuator;
  CLI::App app("vimg-player: play a vibrotactile image full screen at true size. The mouse is one finger; on a "
               "touchscreen every finger plays. Esc or Q quits.");
  cmdline::configure(app, "vimg-player");
  app.add_option("IMAGE", a.image_path, "a .vimg or .png vibrotactile image");
  app.add_option("--output", a.output,
                 "audio | audio:DEVICE | wav:FILE | drv2605l:/dev/i2c-1[,en=gpiochip0:17][,calibration=FILE] | "
                 "spi:/dev/spidev0.0[,mode=0][,speed=HZ] | hid:VID:PID");
  app.add_option("--actuator", actuator, "actuator profile (assets/profiles/*.xml); default: ideal, 175 Hz");
  app.add_flag("--equalize", a.equalize,
               "shape the real-time drive so that the actuator's modelled acceleration follows the designed "
               "intensity across its band (as vimg render --equalize); nothing changes without it");
  auto* scale = app.add_option("--px-per-mm", px_per_mm, "screen scale; default: from the display's DPI")
                    ->check(cmdline::finite_in(0.01, 1000.0));
  app.add_option("--rate", a.rate_hz, "render rate, Hz")->check(cmdline::finite_in(1.0, 48000.0));
  app.add_option("--window", window, "a window of WIDTHxHEIGHT pixels instead of full screen")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            int w = 0, h = 0;
            return parse_window(v, w, h) ? std::string() : "'" + v + "' is not WIDTHxHEIGHT of at least 64x64";
          },
          "WxH"));
  app.add_option("--realtime-priority", a.realtime_priority,
                 "SCHED_FIFO priority 1..99 of the render thread, 0 for none (needs CAP_SYS_NICE or an rtprio "
                 "limit; without it the thread runs normally)")
      ->check(CLI::Range(0, 99));
  app.add_flag("--calibrate", a.calibrate, "run the actuator's calibration (DRV2605L auto-calibration), store it, exit");
  if (const auto code = cmdline::parse(app, arguments)) return {std::nullopt, *code};
  if (a.image_path.empty() && !a.calibrate) {
    std::fprintf(stderr, "vimg-player: error: IMAGE is required (or --calibrate)\nRun 'vimg-player --help' for usage.\n");
    return {std::nullopt, cmdline::kExitUsage};
  }
  if (!actuator.empty()) a.actuator_path = actuator;
  if (scale->count() > 0) a.px_per_mm = px_per_mm;
  if (!window.empty()) {
    int w = 0, h = 0;
    parse_window(window, w, h);
    a.window_size = std::pair{w, h};
  }
  return {a, cmdline::kExitOk};
}

}  // namespace vimg::player_app
