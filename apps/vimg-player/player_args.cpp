#include "apps/vimg-player/player_args.hpp"

#include <charconv>
#include <cstdio>

#include "cmdline/command_line.hpp"
#include "storage/diagnostic.hpp"
#include "storage/study/trial_log.hpp"

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
  app.add_option("--actuator", actuator, "actuator profile: a file, or a shipped profile's name (lra-175hz-drv2605l, erm-10mm, voice-coil-audio, ideal); default: ideal, 175 Hz");
  app.add_flag("--equalize", a.equalize,
               "shape the real-time drive so that the actuator's modelled acceleration follows the designed "
               "intensity across its band (as vimg render --equalize); nothing changes without it");
  auto* scale = app.add_option("--px-per-mm", px_per_mm, "screen scale; default: from the display's DPI")
                    ->check(cmdline::finite_in(0.01, 1000.0));
  app.add_option("--rate", a.rate_hz, "render rate, Hz")->check(cmdline::finite_in(kMinRenderRateHz, kMaxRenderRateHz));
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
  double touch_latency_ms = kDefaultTouchPanelLatency_s * 1e3;
  std::string touch_prediction = "on";
  app.add_option("--touch-latency-ms", touch_latency_ms,
                 "the touch panel's latency in ms (decimals allowed): each finger is predicted this far ahead, plus the "
                 "output's own latency (docs/latency.md)")
      ->capture_default_str()
      ->check(cmdline::finite_in(0.0, kMaxTouchPanelLatency_s * 1e3));
  app.add_option("--touch-prediction", touch_prediction,
                 "on (default): feel each finger where it is, not where the panel last saw it; off: the panel's late "
                 "positions")
      ->check(CLI::IsMember({"on", "off"}));
  app.add_flag("--calibrate", a.calibrate, "run the actuator's calibration (DRV2605L auto-calibration), store it, exit");
  std::string study, responses, gesture;
  auto* study_option = app.add_option("--study", study,
                                      "run the matching test of this study file (docs/player.md, \"Matching test\") "
                                      "instead of playing an image");
  auto* participant = app.add_option("--participant", a.participant,
                                     "the participant's ID ([A-Za-z0-9_-], 1 to 64); names the trial file")
                          ->needs(study_option);
  auto* results = app.add_option("--results", a.results_dir, "folder of the trial files, DIR/ID.trials.csv")
                      ->needs(study_option);
  app.add_flag("--restart", a.restart,
               "begin a finished participant again; the old trial file is kept aside, never overwritten")
      ->needs(study_option);
  auto* responses_option =
      app.add_option("--responses", responses,
                     "scripted run without a person: CSV 'trial,chosen' answering every trial (image by file stem)")
          ->needs(study_option);
  auto* gesture_option =
      app.add_option("--gesture", gesture, "scripted run: the gesture file rubbed in every trial")->needs(study_option);
  responses_option->needs(gesture_option);
  gesture_option->needs(responses_option);
  if (const auto code = cmdline::parse(app, arguments)) return {std::nullopt, *code};
  auto usage_error = [](const std::string& problem) {
    std::fprintf(stderr, "vimg-player: error: %s\nRun 'vimg-player --help' for usage.\n", problem.c_str());
    return ArgsResult{std::nullopt, cmdline::kExitUsage};
  };
  if (study_option->count() > 0) {
    if (study.empty()) return usage_error("--study needs a study file");
    if (!a.image_path.empty() || a.calibrate) return usage_error("--study runs a study: give no IMAGE and no --calibrate");
    if (participant->count() == 0 || results->count() == 0) return usage_error("--study needs --participant and --results");
    if (!valid_participant_id(a.participant)) {
      return usage_error("--participant '" + escape_input(a.participant) + "': an ID is 1 to 64 letters, digits, '_' or '-'");
    }
    if (a.results_dir.empty()) return usage_error("--results needs a folder");
    a.study_path = study;
    if (!responses.empty()) a.responses_path = responses;
    if (!gesture.empty()) a.gesture_path = gesture;
  } else if (a.image_path.empty() && !a.calibrate) {
    return usage_error("IMAGE is required (or --calibrate, or --study)");
  }
  a.touch.panel_latency_s = touch_latency_ms * 1e-3;
  a.touch.enabled = touch_prediction == "on";
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
