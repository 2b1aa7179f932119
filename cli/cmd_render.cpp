// `vimg render IMAGE --gesture G.csv --out OUT.(wav|csv) [--rate HZ]` (spec section 4).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "cli/command.hpp"
#include "hal/actuator_profile.hpp"
#include "hal/drv2605l_trace_sink.hpp"
#include "player/drive_sinks.hpp"
#include "player/gesture.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "storage/image_io.hpp"

namespace vimg::cli {

namespace {

constexpr std::string_view kRenderUsage =
    "vimg render IMAGE --gesture G.csv --out OUT.(wav|csv) [--rate HZ] [--actuator PROFILE] "
    "[--register-trace FILE.csv]";

int usage_error(const std::string& problem) {
  std::fprintf(stderr, "vimg render: %s\nusage: %.*s\n", problem.c_str(), static_cast<int>(kRenderUsage.size()),
               kRenderUsage.data());
  return kExitUsage;
}

std::string lower_extension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

struct RenderArgs {
  std::string image;
  std::string gesture;
  std::string out;
  double rate_hz = 8000.0;
  // Options of the hardware layer (actuator profile) go in the block marked below.
  std::string actuator;        // profile file; empty: the ideal actuator
  std::string register_trace;  // DRV2605L register traffic CSV; needs a drv2605l profile
};

// Parses the arguments; returns an exit code on a usage error.
std::optional<int> parse_render_args(std::span<const std::string_view> args, RenderArgs& out) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view a = args[i];
    auto value = [&](std::string_view& v) {
      if (i + 1 >= args.size()) return false;
      v = args[++i];
      return true;
    };
    std::string_view v;
    if (a == "--gesture") {
      if (!value(v)) return usage_error("--gesture needs a file");
      out.gesture = std::string(v);
    } else if (a == "--out") {
      if (!value(v)) return usage_error("--out needs a file");
      out.out = std::string(v);
    } else if (a == "--rate") {
      if (!value(v)) return usage_error("--rate needs a value in Hz");
      int rate = 0;
      const auto r = std::from_chars(v.data(), v.data() + v.size(), rate);
      if (r.ec != std::errc{} || r.ptr != v.data() + v.size() || rate < 1 || rate > 48000)
        return usage_error("--rate must be a whole number of Hz in 1..48000, not '" + std::string(v) + "'");
      out.rate_hz = rate;
    }
    // ---- hardware layer options (e.g. --actuator PROFILE) ----
    else if (a == "--actuator") {
      if (!value(v)) return usage_error("--actuator needs a profile file");
      out.actuator = std::string(v);
    } else if (a == "--register-trace") {
      if (!value(v)) return usage_error("--register-trace needs a file");
      out.register_trace = std::string(v);
    }
    // ---- end of hardware layer options ----
    else if (a.size() > 1 && a.front() == '-') {
      return usage_error("unknown option '" + std::string(a) + "'");
    } else if (out.image.empty()) {
      out.image = std::string(a);
    } else {
      return usage_error("unexpected argument '" + std::string(a) + "'");
    }
  }
  if (out.image.empty()) return usage_error("missing IMAGE");
  if (out.gesture.empty()) return usage_error("missing --gesture G.csv");
  if (out.out.empty()) return usage_error("missing --out OUT.wav or OUT.csv");
  const std::string ext = lower_extension(out.out);
  if (ext != ".wav" && ext != ".csv") return usage_error("--out must end in .wav or .csv: '" + out.out + "'");
  if (!out.register_trace.empty() && out.actuator.empty())
    return usage_error("--register-trace needs --actuator with a drv2605l profile");
  return std::nullopt;
}

int run_render(std::span<const std::string_view> args) {
  RenderArgs a;
  if (auto code = parse_render_args(args, a)) return *code;

  const LoadResult loaded = load_image_file(a.image);
  for (const Diagnostic& d : loaded.diagnostics) std::fprintf(stderr, "%s\n", d.to_string().c_str());
  if (!loaded.ok()) {
    if (loaded.diagnostics.empty()) std::fprintf(stderr, "%s: error: cannot load the image\n", a.image.c_str());
    return kExitFailure;
  }
  const GestureParseResult gesture = load_gesture_file(a.gesture);
  for (const std::string& e : gesture.errors) std::fprintf(stderr, "%s\n", e.c_str());
  if (!gesture.ok()) return kExitFailure;

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
  } else {
    sink = std::make_unique<CsvSink>(a.out);
  }
  OfflineRenderOptions options;
  options.sample_rate_hz = a.rate_hz;
  std::unique_ptr<Drv2605lTraceSink> trace;
  if (!a.register_trace.empty()) {
    try {
      trace = std::make_unique<Drv2605lTraceSink>(*sink, profile, a.register_trace);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "vimg render: %s: %s\n", a.actuator.c_str(), e.what());
      return kExitFailure;
    }
  }
  const OfflineRenderResult r =
      render_gesture(*scene, *gesture.gesture, trace ? static_cast<DriveSink&>(*trace) : *sink, options);
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

int render_command(std::span<const std::string_view> args) { return run_render(args); }

}  // namespace vimg::cli
