#pragma once
// Command line of vimg-player.
#include <optional>
#include <string>
#include <vector>

namespace vimg::player_app {

inline constexpr const char* kUsage =
    "usage: vimg-player IMAGE [--output SPEC] [--actuator PROFILE.xml] [--px-per-mm N] [--rate HZ]\n"
    "                   [--window WIDTHxHEIGHT] [--realtime-priority N] [--calibrate]\n"
    "  IMAGE               a .vimg or .png vibrotactile image\n"
    "  --output SPEC       audio | audio:DEVICE | wav:FILE | drv2605l:/dev/i2c-1[,en=gpiochip0:17]\n"
    "                      [,calibration=FILE] | spi:/dev/spidev0.0[,mode=0][,speed=HZ] | hid:VID:PID\n"
    "                      (default: audio)\n"
    "  --actuator FILE     actuator profile (assets/profiles/*.xml); default: ideal, 175 Hz\n"
    "  --px-per-mm N       screen scale; default: from the display's DPI\n"
    "  --rate HZ           render rate; default 8000\n"
    "  --window WxH        a window instead of full screen\n"
    "  --realtime-priority N  SCHED_FIFO priority 1..99 of the render thread, 0 for none; default 80\n"
    "                      (needs CAP_SYS_NICE or an rtprio limit; without it the thread runs normally)\n"
    "  --calibrate         run the actuator's calibration (DRV2605L auto-calibration), store it, exit\n"
    "Mouse: the mouse is one finger. Touch: every finger plays. Esc or Q quits.\n";

struct PlayerArgs {
  std::string image_path;
  std::string output = "audio";
  std::optional<std::string> actuator_path;
  std::optional<double> px_per_mm;
  double rate_hz = 8000.0;
  std::optional<std::pair<int, int>> window_size;
  bool calibrate = false;
  int realtime_priority = 80;  // SCHED_FIFO for the render thread: steady latency on a busy device
};

struct ArgsResult {
  std::optional<PlayerArgs> args;
  std::string error;  // empty with no args: --help
};

ArgsResult parse_player_args(const std::vector<std::string>& arguments);

}  // namespace vimg::player_app
