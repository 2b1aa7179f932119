// `vimg render IMAGE --gesture G.csv --out OUT.(wav|csv) [--rate HZ] [--actuator P]
//  [--signal drive|acceleration] [--equalize] [--touch-latency-ms L [--touch-prediction on|off]]`
// (spec section 4, docs/actuators.md, docs/latency.md).
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.hpp"
#include "storage/actuator_profile.hpp"
#include "hal/drv2605l_trace_sink.hpp"
#include "hal/rest_on_exit.hpp"
#include "player/actuator_sink.hpp"
#include "player/clip_export/clip_sink.hpp"
#include "player/drive_sinks.hpp"
#include "storage/gesture_csv.hpp"
#include "player/offline_render.hpp"
#include "primitives/touch_prediction/touch_latency_defaults.hpp"
#include "player/scene.hpp"
#include "storage/export/clip_metadata.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/file_extension.hpp"
#include "storage/print_diagnostics.hpp"

namespace vimg::cli {

namespace {

struct RenderArgs {
  std::string image;
  std::string gesture;
  std::string out;
  int rate_hz = static_cast<int>(kDefaultRenderRateHz);
  // Options of the hardware layer (actuator profile) go in the block marked below.
  std::string actuator;        // profile file; empty: the ideal actuator
  std::string register_trace;  // DRV2605L register traffic CSV; needs a drv2605l profile
  std::string signal = "drive";  // drive | acceleration (the modelled acceleration of the actuator)
  bool equalize = false;         // shape the drive to the actuator's response
  // A simulated touch panel that reports every row this late, and the live player's compensation.
  double touch_latency_ms = -1.0;  // < 0: no panel (the gesture is played exactly)
  std::string touch_prediction = "on";
};

// Progress on stderr for renders longer than this much gesture time, every kProgressStep of it.
constexpr double kProgressAfter_s = 60.0;
constexpr double kProgressStep_s = 30.0;

struct Progress {
  double next_s = kProgressStep_s;
};

void report_progress(double rendered_s, double end_s, void* context) {
  auto& p = *static_cast<Progress*>(context);
  if (rendered_s < p.next_s) return;
  std::fprintf(stderr, "vimg render: %.0f of %.0f s rendered\n", std::min(rendered_s, end_s), end_s);
  p.next_s = rendered_s + kProgressStep_s;
}

// The checks CLI11 cannot express; returns an exit code on a usage error.
std::optional<int> check_render_args(const RenderArgs& a) {
  const std::string ext = lower_extension(a.out);
  if (ext != ".wav" && ext != ".csv" && !is_clip_extension(a.out))
    return usage_error("vimg render", "--out must end in .wav, .csv, .ahap or .haptic: '" + a.out + "'");
  if (!a.register_trace.empty() && a.actuator.empty())
    return usage_error("vimg render", "--register-trace needs --actuator with a drv2605l profile");
  if (a.touch_latency_ms < 0.0 && a.touch_prediction != "on")
    return usage_error("vimg render", "--touch-prediction needs --touch-latency-ms (the simulated panel)");
  if (!a.register_trace.empty() && a.signal == "acceleration")
    return usage_error("vimg render", "--register-trace records the drive: it does not go with --signal acceleration");
  return std::nullopt;
}

int run_render(const RenderArgs& a) {
  if (auto code = check_render_args(a)) return *code;

  const LoadResult loaded = load_image_file(a.image);
  print_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) {
    if (loaded.diagnostics.empty()) std::fprintf(stderr, "%s: error: cannot load the image\n", a.image.c_str());
    return kExitFailure;
  }
  const GestureParseResult gesture = load_gesture_file(a.gesture);
  for (const std::string& e : gesture.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!gesture.ok()) return kExitFailure;
  // The output starts at time 0 (or at the gesture, if it starts earlier): bound what that costs.
  const double span_s = std::max(0.0, gesture.gesture->end_time_s()) - std::min(0.0, gesture.gesture->start_time_s());
  if (span_s > kMaxGestureDurationS) {
    std::fprintf(stderr, "%s: error: the render would last %.0f s from time 0 (limit %.0f s); shift the times to start near 0\n",
                 a.gesture.c_str(), span_s, kMaxGestureDurationS);
    return kExitFailure;
  }

  OfflineRenderOptions options;
  if (a.touch_latency_ms >= 0.0) {
    if (const std::string problem = panel_simulation_problem(*gesture.gesture); !problem.empty()) {
      std::fprintf(stderr, "%s: error: %s\n", a.gesture.c_str(), problem.c_str());
      return kExitFailure;
    }
    options.panel = PanelSimulation{a.touch_latency_ms * 1e-3, a.touch_prediction == "on", kDefaultTouchPredictionModel};
  }
  ActuatorProfile profile;  // the ideal actuator: resonance 175 Hz as the DOT carrier
  if (!a.actuator.empty()) {
    const ProfileLoadResult loaded_profile = load_actuator_profile(a.actuator);
    for (const std::string& e : loaded_profile.errors) std::fprintf(stderr, "%s\n", e.c_str());
    if (!loaded_profile.profile) return kExitFailure;
    profile = *loaded_profile.profile;
  }
  SceneOptions scene_options;
  scene_options.carrier_frequency_hz = profile.resonance_hz;
  const auto scene = compile_scene(*loaded.image, scene_options);
  std::unique_ptr<FileSink> sink;
  if (lower_extension(a.out) == ".wav") {
    sink = std::make_unique<WavSink>(a.out);
  } else if (is_clip_extension(a.out)) {  // a phone haptics clip of the drive (docs/export.md)
    sink = std::make_unique<ClipSink>(
        a.out, clip_metadata(*loaded.image, a.image, a.gesture, std::string("vimg ") + cmdline::version()));
  } else {
    sink = std::make_unique<CsvSink>(a.out, a.signal);
  }
  sink->set_new_file_mode(NewFileMode::of(a.image));  // a new output takes the image's permission bits
  options.sample_rate_hz = static_cast<double>(a.rate_hz);
  const OutputSignal signal = a.signal == "acceleration" ? OutputSignal::acceleration : OutputSignal::drive;
  if (a.equalize && profile.response.model == ResponseModel::erm) {
    std::fprintf(stderr, "vimg render: warning: --equalize does nothing for an erm profile (a filter cannot reshape a motor's spin-up)\n");
  }
  // SIGINT/SIGTERM only set a flag; the render stops at the next block and the output is abandoned.
  const SignalRestScope signals;
  options.should_stop = [] { return rest_requested(); };
  Progress progress;
  if (gesture.gesture->end_time_s() - std::min(0.0, gesture.gesture->start_time_s()) > kProgressAfter_s) {
    options.progress = report_progress;
    options.progress_context = &progress;
  }
  std::unique_ptr<Drv2605lTraceSink> trace;
  if (!a.register_trace.empty()) {
    try {
      trace = std::make_unique<Drv2605lTraceSink>(*sink, profile, a.register_trace);
      trace->set_new_file_mode(NewFileMode::of(a.image));
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "vimg render: %s: %s\n", a.actuator.c_str(), e.what());
      return kExitFailure;
    }
  }
  // The drive through the actuator chain (the equalizer, the modelled acceleration), then the
  // register trace if any, then the file.
  ActuatorSink shaped(trace ? static_cast<DriveSink&>(*trace) : *sink, profile.response, signal, a.equalize);
  const OfflineRenderResult r = render_gesture(*scene, *gesture.gesture, shaped, options);
  if (r.interrupted) {
    sink->abort();
    std::fprintf(stderr, "vimg render: interrupted; %s not written\n", a.out.c_str());
    return rest_signal() == SIGTERM ? cmdline::kExitSigterm : cmdline::kExitSigint;
  }
  if (trace && trace->error()) {
    std::fprintf(stderr, "vimg render: %s\n", trace->error()->c_str());
    return kExitFailure;
  }
  if (sink->error()) {
    std::fprintf(stderr, "vimg render: %s\n", sink->error()->c_str());
    return kExitFailure;
  }
  if (r.refused_contacts > 0) {
    std::fprintf(stderr, "vimg render: warning: %llu contacts exceeded the contact pool and were not rendered\n",
                 static_cast<unsigned long long>(r.refused_contacts));
  }
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& vimg, int& exit_code) {
  CLI::App* sub = vimg.add_subcommand("render", "render the drive (or the modelled acceleration) of a gesture over an image (mono float WAV or time_s,drive CSV)");
  auto a = std::make_shared<RenderArgs>();
  sub->add_option("IMAGE", a->image, "a .vimg or .png image")->required();
  sub->add_option("--gesture", a->gesture, "the gesture CSV (time_s,finger,x_mm,y_mm,pressure,phase)")->required();
  sub->add_option("--out", a->out, "OUT.wav (mono 32-bit float), OUT.csv (time_s,drive or time_s,acceleration), or a phone clip OUT.ahap (Apple) or OUT.haptic (Meta), written atomically")->required();
  sub->add_option("--rate", a->rate_hz, "output sample rate in Hz")->check(CLI::Range(static_cast<int>(kMinRenderRateHz), static_cast<int>(kMaxRenderRateHz)));
  sub->add_option("--actuator", a->actuator, "actuator profile: a file, or a shipped profile's name (lra-175hz-drv2605l, erm-10mm, voice-coil-audio, ideal); default: ideal, 175 Hz carrier");
  sub->add_option("--register-trace", a->register_trace, "DRV2605L register traffic as CSV (needs a drv2605l --actuator)");
  sub->add_option("--signal", a->signal,
                  "drive (default: what the actuator is given) or acceleration (what the actuator's response model makes "
                  "of it; the ideal actuator gives the drive unchanged); names the CSV column")
      ->check(CLI::IsMember({"drive", "acceleration"}));
  sub->add_flag("--equalize", a->equalize,
                "shape the drive so that the modelled acceleration follows the design across the actuator's band "
                "(attenuates the resonance; |drive| stays <= 1)");
  sub->add_option("--touch-latency-ms", a->touch_latency_ms,
                  "simulate a touch panel that reports every row this many ms late (decimals allowed), with the live "
                  "players' compensation (docs/latency.md)")
      ->check(cmdline::finite_in(0.0, kMaxTouchPanelLatency_s * 1e3));
  sub->add_option("--touch-prediction", a->touch_prediction,
                  "on (default): predict each finger the panel's latency ahead, as the live players do; off: the late "
                  "positions alone")
      ->check(CLI::IsMember({"on", "off"}));
  sub->footer("Limits (docs/limits.md): a gesture of at most " + std::to_string(kMaxGestureRows) + " rows, " +
              std::to_string(static_cast<int>(kMaxGestureDurationS)) + " s from time 0 and " +
              std::to_string(kMaxCsvFileBytes >> 20) + " MiB; an image of at most " + std::to_string(kMaxImageFileBytes >> 20) +
              " MiB. SIGINT/SIGTERM abandon the output and exit 130/143.");
  sub->callback([a, &exit_code] { exit_code = run_render(*a); });
}

}  // namespace vimg::cli
