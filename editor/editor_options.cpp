#include "editor/editor_options.hpp"

#include <charconv>

#include "cmdline/command_line.hpp"

namespace vimg::editor {
namespace {

// "WxH" with whole pixel counts of at least 320x240.
CLI::Validator window_size() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        int w = 0, h = 0;
        if (!parse_window_size(input, w, h)) return "'" + input + "' is not WxH of at least 320x240 pixels";
        return {};
      },
      "WxH");
}

}  // namespace

bool parse_window_size(const std::string& text, int& width_px, int& height_px) {
  const auto x = text.find('x');
  if (x == std::string::npos) return false;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto w = std::from_chars(begin, begin + x, width_px);
  const auto h = std::from_chars(begin + x + 1, end, height_px);
  return w.ec == std::errc() && w.ptr == begin + x && h.ec == std::errc() && h.ptr == end && width_px >= 320 &&
         height_px >= 240;
}

ParsedOptions parse_editor_options(int argc, char** argv) {
  EditorOptions o;
  std::string output = "audio", size, touch_prediction = "on";
  double touch_latency_ms = 0.0;
  CLI::App app("vimg-editor: draw vibrotactile images and play them (F5).");
  cmdline::configure(app, "vimg-editor");
  app.add_option("FILE", o.file, "a .vimg or .png vibrotactile image to open");
  app.add_option("--output", output,
                 "playing-mode output: audio[:DEVICE], wav:FILE, csv:FILE, drv2605l:/dev/i2c-N[,en=CHIP:LINE], "
                 "spi:/dev/spidevB.C, hid:VID:PID, none")
      ->check(CLI::Validator(
          [](std::string& input) -> std::string {
            const OutputChoiceResult parsed = parse_output_choice(input);
            return parsed.choice ? std::string() : parsed.error;
          },
          "OUT"));
  app.add_option("--actuator", o.actuator,
                 "actuator profile to design for (a file, or a shipped profile's name such as lra-175hz-drv2605l): the scope shows its predicted acceleration "
                 "and the canvas marks primitives it barely renders; default: ideal");
  app.add_option("--rate", o.sample_rate_hz, "output sample rate, Hz")->check(cmdline::finite_in(kMinRenderRateHz, kMaxRenderRateHz));
  touch_latency_ms = o.touch.panel_latency_s * 1e3;
  CLI::Option* latency_option = app.add_option("--touch-latency-ms", touch_latency_ms,
                 "the pointing device's latency in ms (decimals allowed): playing mode feels each finger this far "
                 "ahead plus the output's own latency (docs/latency.md); default: the Mode menu's last choice on this device")
      ->capture_default_str()
      ->check(cmdline::finite_in(0.0, kMaxTouchPanelLatency_s * 1e3));
  CLI::Option* prediction_option =
      app.add_option("--touch-prediction", touch_prediction, "on (default) or off: predict each finger in playing mode")
          ->check(CLI::IsMember({"on", "off"}));
  app.add_option("--recovery-dir", o.recovery_dir, "where autosave keeps the recovery file");
  app.add_option("--autosave-interval", o.autosave_interval_s, "seconds between autosaves of unsaved changes")
      ->check(cmdline::finite_in(0.1, 86400.0));
  app.add_option("--library-dir", o.library_dir, "your library folder (default ~/vibroimages)");
  app.add_option("--zoom", o.zoom, "initial zoom, 1 = physical size")->check(cmdline::finite_in(0.01, 100.0));
  app.add_option("--px-per-mm", o.px_per_mm, "screen density (default: from the display)")
      ->check(cmdline::finite_in(0.1, 1000.0));
  app.add_option("--size", size, "window size in pixels (default 1280x800)")->check(window_size());
  app.add_flag("--play", o.play_at_start, "start in playing mode");
  app.add_option("--record-gesture", o.record_gesture, "record the gesture in playing mode and write it to FILE (CSV)");
  app.add_flag("--print-layout", o.print_layout, "print canvas and widget positions on stdout (scripted tests)");
  app.add_option("--benchmark-frames", o.benchmark_frames, "draw N frames as fast as possible, print frame times, exit")
      ->check(CLI::Range(1, 1'000'000));
  if (const auto code = cmdline::parse(app, argc, argv)) return ParsedOptions{std::nullopt, *code};
  o.output = *parse_output_choice(output).choice;
  if (!size.empty()) parse_window_size(size, o.width_px, o.height_px);
  o.touch.panel_latency_s = touch_latency_ms * 1e-3;
  o.touch.enabled = touch_prediction == "on";
  o.touch_latency_given = latency_option->count() > 0;
  o.touch_prediction_given = prediction_option->count() > 0;
  return ParsedOptions{o, cmdline::kExitOk};
}

}  // namespace vimg::editor
