#pragma once
// The command line of vimg-editor (`vimg-editor --help` lists it).
#include <optional>
#include <string>

#include "editor/output_choice.hpp"
#include "player/realtime_renderer.hpp"

namespace vimg::editor {

struct EditorOptions {
  std::string file;                 // opened at start (may be empty)
  std::string recovery_dir;         // empty: RecoveryStore::default_dir()
  std::string library_dir;          // the user's library folder; empty: ~/vibroimages
  std::string record_gesture;       // record in playing mode and write the gesture here on stop
  std::string actuator;             // actuator profile to design for; empty: the ideal actuator
  OutputChoice output;
  double sample_rate_hz = kDefaultRenderRateHz;
  double autosave_interval_s = 5.0;
  double zoom = 1.0;                // 1 = physical size
  double px_per_mm = 0.0;           // 0: from the display's DPI
  int width_px = 1280;
  int height_px = 800;
  bool print_layout = false;        // print where widgets are (for scripted tests)
  int benchmark_frames = 0;         // render this many frames as fast as possible, report, exit
  bool play_at_start = false;
  // Touch-latency compensation in playing mode (docs/latency.md): --touch-latency-ms (default the
  // mouse's, the editor's usual input), --touch-prediction; the Mode menu changes both.
  // The Mode menu's choice is kept on this device (the config folder's touch-latency.txt,
  // storage/touch_settings_file.hpp) and used at the next start unless the command line gives it.
  TouchCompensation touch{true, kDefaultMousePanelLatency_s, kDefaultTouchPredictionModel};
  bool touch_latency_given = false;     // --touch-latency-ms was on the command line
  bool touch_prediction_given = false;  // --touch-prediction was
};

struct ParsedOptions {
  std::optional<EditorOptions> options;  // empty: exit with `exit_code` (help, version or usage error, printed)
  int exit_code = 0;
};

// Parses the command line with the project's conventions (cmdline/command_line.hpp).
ParsedOptions parse_editor_options(int argc, char** argv);

// "WxH", whole pixels, at least 320x240.
bool parse_window_size(const std::string& text, int& width_px, int& height_px);

}  // namespace vimg::editor
