#pragma once
// Command line of vimg-player (`vimg-player --help` lists it), parsed with the project's
// conventions (cmdline/command_line.hpp).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "player/realtime_renderer.hpp"

namespace vimg::player_app {

struct PlayerArgs {
  std::string image_path;
  std::string output = "audio";
  std::optional<std::string> actuator_path;
  std::optional<double> px_per_mm;
  double rate_hz = kDefaultRenderRateHz;
  std::optional<std::pair<int, int>> window_size;
  bool calibrate = false;
  bool equalize = false;       // equalize the drive for the actuator (ActuatorChain, --equalize)
  int realtime_priority = 80;  // SCHED_FIFO for the render thread: steady latency on a busy device
  // Touch-latency compensation (docs/latency.md): on by default, --touch-latency-ms, --touch-prediction.
  TouchCompensation touch{true, kDefaultTouchPanelLatency_s, kDefaultTouchPredictionModel};
  // The matching test (docs/player.md, "Matching test"): --study instead of IMAGE.
  std::optional<std::string> study_path;
  std::string participant;  // [A-Za-z0-9_-]{1,64}
  std::string results_dir;
  bool restart = false;
  // Scripted run (no person): both or neither.
  std::optional<std::string> responses_path;
  std::optional<std::string> gesture_path;
};

struct ArgsResult {
  std::optional<PlayerArgs> args;
  int exit_code = 0;  // when args is empty: 0 (help, version) or 2 (usage error), already printed
};

// The arguments after the program name.
ArgsResult parse_player_args(const std::vector<std::string>& arguments);

}  // namespace vimg::player_app
