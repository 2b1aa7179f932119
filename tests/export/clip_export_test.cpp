// Phone haptics export: the AHAP and .haptic files are well-formed as their published structures
// say (docs/export.md), and the amplitude envelope follows the rendered drive.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <unistd.h>
#include <sys/wait.h>
#include <random>
#include <sstream>

#include "json_reader.hpp"
#include "player/clip_export/clip_sink.hpp"
#include "player/clip_export/drive_envelope.hpp"
#include "player/drive_sinks.hpp"
#include "player/gesture_synth.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "storage/export/haptic_clip.hpp"
#include "storage/export/json_writer.hpp"

namespace vimg {
namespace {

using test::Json;
using test::JsonReader;

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(JsonWriter, StringsAreEscapedAndAlwaysValidUtf8) {
  const std::string tricky = std::string("quote\" back\\ tab\t nl\n nul") + '\0' + " é \xff\xfe end";
  JsonWriter w;
  w.begin_object();
  w.key("s");
  w.string(tricky);
  w.key("n");
  w.number(0.1);
  w.key("inf");
  w.number(INFINITY);
  w.key("empty");
  w.begin_array();
  w.end_array();
  w.end_object();
  const Json j = JsonReader::parse(w.take());
  EXPECT_EQ(j["s"].string(), std::string("quote\" back\\ tab\t nl\n nul") + '\0' + " é \xEF\xBF\xBD\xEF\xBF\xBD end");
  EXPECT_EQ(j["n"].number(), 0.1);
  EXPECT_EQ(j["inf"].number(), 0.0);
  EXPECT_TRUE(j["empty"].array().empty());
}

// The value of piecewise-linear breakpoints at time t.
double at(const std::vector<ClipBreakpoint>& points, double t) {
  if (t <= points.front().time_s) return points.front().value;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (t <= points[i].time_s) {
      const double u = (t - points[i - 1].time_s) / (points[i].time_s - points[i - 1].time_s);
      return points[i - 1].value + u * (points[i].value - points[i - 1].value);
    }
  }
  return points.back().value;
}

TEST(MergeLinear, DroppedBreakpointsStayWithinTheTolerance) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> value(0.0, 1.0);
  std::vector<ClipBreakpoint> points;
  for (int i = 0; i < 400; ++i) points.push_back({i * 0.005, i % 50 < 25 ? 0.5 + 0.004 * (i % 25) : value(rng)});
  const std::vector<ClipBreakpoint> merged = merge_linear(points, 0.02, {7});
  EXPECT_LT(merged.size(), points.size());
  EXPECT_EQ(merged.front().time_s, points.front().time_s);
  EXPECT_EQ(merged.back().time_s, points.back().time_s);
  EXPECT_TRUE(std::any_of(merged.begin(), merged.end(), [&](const ClipBreakpoint& p) { return p.time_s == points[7].time_s; }));
  for (const ClipBreakpoint& p : points) EXPECT_LE(std::fabs(at(merged, p.time_s) - p.value), 0.02 + 1e-12) << p.time_s;
  // A straight ramp is two breakpoints.
  std::vector<ClipBreakpoint> ramp;
  for (int i = 0; i <= 100; ++i) ramp.push_back({i * 0.01, i / 100.0});
  EXPECT_EQ(merge_linear(ramp, 0.02).size(), 2u);
}

TEST(DriveEnvelope, ASineGivesItsAmplitudeAndFrequency) {
  const double rate = 8000.0, f = 175.0, a = 0.6;
  std::vector<float> s(8000);
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<float>(a * std::sin(2 * std::numbers::pi * f * static_cast<double>(i) / rate));
  DriveEnvelope env(rate);
  env.add(s);
  const auto windows = env.windows();
  ASSERT_EQ(windows.size(), 200u);
  for (std::size_t i = 2; i < windows.size(); ++i) {
    EXPECT_NEAR(windows[i].amplitude, a, 0.1 * a);  // a 5 ms window holds 0.875 periods
    EXPECT_NEAR(windows[i].frequency_hz, f, 0.01 * f);
  }
  const HapticClip clip = env.clip();
  EXPECT_DOUBLE_EQ(clip.duration_s, 1.0);
  // docs/export.md: log(175 / 40) / log(500 / 40) = 0.584 (175 Hz measured within 1 %: +-0.004).
  EXPECT_NEAR(clip.frequency.back().value, 0.584, 0.005);
}

TEST(DriveEnvelope, FrequenciesAreNormalisedAsTheDocsDerive) {
  EXPECT_NEAR(clip_frequency_from_hz(175.0), 0.5844, 1e-4);
  EXPECT_EQ(clip_frequency_from_hz(40.0), 0.0);
  EXPECT_NEAR(clip_frequency_from_hz(500.0), 1.0, 1e-12);
  EXPECT_NEAR(clip_frequency_from_hz(141.42135623730951), 0.5, 1e-9);  // the geometric middle
  EXPECT_EQ(clip_frequency_from_hz(20.0), 0.0);   // clamped
  EXPECT_EQ(clip_frequency_from_hz(2000.0), 1.0);
}

// The value of the AHAP event parameter `id` (-1 when absent).
double event_parameter(const Json& event, const std::string& id) {
  for (const Json& p : event["EventParameters"].array()) {
    if (p["ParameterID"].string() == id) return p["ParameterValue"].number();
  }
  return -1.0;
}

TEST(DriveEnvelope, AnOnsetIsATransientWithABreakpointAtItsTime) {
  const double rate = 8000.0;
  std::vector<float> s(4000, 0.0f);
  for (std::size_t i = 2000; i < 2400; ++i) s[i] = static_cast<float>(0.9 * std::sin(2 * std::numbers::pi * 175.0 * static_cast<double>(i - 2000) / rate));
  DriveEnvelope env(rate);
  env.add(s);
  const HapticClip clip = env.clip();
  ASSERT_EQ(clip.transients.size(), 1u);
  const ClipTransient& click = clip.transients[0];
  EXPECT_NEAR(click.time_s, 0.25, 0.006);
  // Its amplitude is its window's, sqrt(2) RMS of 0.875 periods of a 0.9 sine: 0.94 (within 10 %
  // of 0.9), its frequency the next window's, 175 Hz: 0.584.
  EXPECT_NEAR(click.amplitude, 0.94, 0.02);
  EXPECT_NEAR(click.frequency, 0.584, 0.005);
  EXPECT_TRUE(std::any_of(clip.amplitude.begin(), clip.amplitude.end(),
                          [&](const ClipBreakpoint& p) { return p.time_s == click.time_s; }));

  // AHAP: a HapticTransient at its time, intensity sqrt(amplitude), sharpness sqrt(frequency).
  int transients = 0;
  const Json ahap = JsonReader::parse(write_ahap(clip));
  for (const Json& item : ahap["Pattern"].array()) {
    if (!item.has("Event") || item["Event"]["EventType"].string() != "HapticTransient") continue;
    ++transients;
    EXPECT_NEAR(item["Event"]["Time"].number(), click.time_s, 1e-9);
    EXPECT_NEAR(event_parameter(item["Event"], "HapticIntensity"), std::sqrt(click.amplitude), 1e-9);
    EXPECT_NEAR(event_parameter(item["Event"], "HapticSharpness"), std::sqrt(click.frequency), 1e-9);
    EXPECT_NEAR(event_parameter(item["Event"], "HapticSharpness"), std::sqrt(0.584), 0.005);
  }
  EXPECT_EQ(transients, 1);
  // .haptic: the emphasis of the amplitude breakpoint at its time, linear values; no other emphasis.
  int emphasised = 0;
  const Json haptic = JsonReader::parse(write_meta_haptic(clip));
  for (const Json& p : haptic["signals"]["continuous"]["envelopes"]["amplitude"].array()) {
    if (!p.has("emphasis")) continue;
    ++emphasised;
    EXPECT_NEAR(p["time"].number(), click.time_s, 1e-9);
    EXPECT_NEAR(p["emphasis"]["amplitude"].number(), click.amplitude, 1e-9);
    EXPECT_NEAR(p["emphasis"]["frequency"].number(), click.frequency, 1e-9);
  }
  EXPECT_EQ(emphasised, 1);
}

void expect_ascending_in_unit(const Json::Array& points, const char* time_key, const char* value_key) {
  double previous = -1.0;
  for (const Json& p : points) {
    EXPECT_GT(p[time_key].number(), previous);
    previous = p[time_key].number();
    EXPECT_GE(p[value_key].number(), 0.0);
    EXPECT_LE(p[value_key].number(), 1.0);
  }
}

// Checks an AHAP document and returns its intensity curve as absolute breakpoints.
std::vector<ClipBreakpoint> check_ahap(const Json& ahap, double duration_s) {
  EXPECT_EQ(ahap["Version"].number(), 1.0);
  EXPECT_TRUE(ahap["Metadata"].is_object());
  double covered = 0.0;
  std::vector<ClipBreakpoint> intensity;
  ClipBreakpoint last_intensity{-1.0, 0.0};  // the previous curve's last point
  ClipBreakpoint last_sharpness{-1.0, 0.0};
  for (const Json& item : ahap["Pattern"].array()) {
    if (item.has("Event")) {
      const Json& e = item["Event"];
      const std::string& type = e["EventType"].string();
      EXPECT_TRUE(type == "HapticContinuous" || type == "HapticTransient") << type;
      EXPECT_GE(e["Time"].number(), 0.0);
      EXPECT_LE(e["Time"].number(), duration_s);
      for (const Json& p : e["EventParameters"].array()) {
        EXPECT_GE(p["ParameterValue"].number(), 0.0);
        EXPECT_LE(p["ParameterValue"].number(), 1.0);
      }
      if (type == "HapticContinuous") {
        EXPECT_NEAR(e["Time"].number(), covered, 1e-9);  // events follow each other
        EXPECT_LE(e["EventDuration"].number(), kAhapMaxContinuousS);
        covered += e["EventDuration"].number();
      }
      continue;
    }
    const Json& c = item["ParameterCurve"];
    const std::string& id = c["ParameterID"].string();
    EXPECT_TRUE(id == "HapticIntensityControl" || id == "HapticSharpnessControl") << id;
    const Json::Array& points = c["ParameterCurveControlPoints"].array();
    EXPECT_LE(points.size(), kAhapMaxCurvePoints);
    EXPECT_EQ(points.front()["Time"].number(), 0.0);  // times relative to the curve
    expect_ascending_in_unit(points, "Time", "ParameterValue");
    // Each curve after the first starts with the last point of the one before (same time, same
    // value), so that the value is continuous; that shared point is taken once.
    ClipBreakpoint& last = id == "HapticIntensityControl" ? last_intensity : last_sharpness;
    const double curve_s = c["Time"].number();
    if (last.time_s >= 0.0) {
      EXPECT_NEAR(curve_s, last.time_s, 1e-9) << id;
      EXPECT_EQ(points.front()["ParameterValue"].number(), last.value) << id << " at " << curve_s;
    }
    for (std::size_t k = last.time_s >= 0.0 ? 1 : 0; k < points.size(); ++k) {
      const double v = points[k]["ParameterValue"].number();
      if (id == "HapticIntensityControl") intensity.push_back({curve_s + points[k]["Time"].number(), v * v});  // intensity = sqrt(amplitude)
    }
    last = {curve_s + points.back()["Time"].number(), points.back()["ParameterValue"].number()};
  }
  EXPECT_NEAR(covered, duration_s, 1e-9);
  return intensity;
}

std::vector<ClipBreakpoint> check_haptic(const Json& h) {
  EXPECT_EQ(h["version"]["major"].number(), 1);
  EXPECT_EQ(h["version"]["minor"].number(), 0);
  EXPECT_EQ(h["version"]["patch"].number(), 0);
  for (const char* key : {"editor", "source", "project", "description"}) EXPECT_TRUE(h["metadata"][key].is_string()) << key;
  EXPECT_TRUE(h["metadata"]["tags"].is_array());
  const Json& envelopes = h["signals"]["continuous"]["envelopes"];
  expect_ascending_in_unit(envelopes["amplitude"].array(), "time", "amplitude");
  expect_ascending_in_unit(envelopes["frequency"].array(), "time", "frequency");
  std::vector<ClipBreakpoint> amplitude;
  for (const Json& p : envelopes["amplitude"].array()) {
    amplitude.push_back({p["time"].number(), p["amplitude"].number()});
    if (p.has("emphasis")) {
      for (const char* key : {"amplitude", "frequency"}) {
        EXPECT_GE(p["emphasis"][key].number(), 0.0);
        EXPECT_LE(p["emphasis"][key].number(), 1.0);
      }
    }
  }
  return amplitude;
}

TEST(ClipWriters, LongClipsSplitIntoThirtySecondEventsAndSixteenPointCurves) {
  HapticClip clip;
  clip.duration_s = 70.0;
  for (int i = 0; i <= 700; ++i) clip.amplitude.push_back({i * 0.1, 0.5 + 0.5 * std::sin(i * 0.3)});
  clip.frequency = {{0.0, 0.2}, {70.0, 0.8}};
  clip.transients = {{1.0, 0.9, 0.5}};
  clip.metadata.source = "a \"quoted\" name.vimg";
  const Json ahap = JsonReader::parse(write_ahap(clip));
  const std::vector<ClipBreakpoint> intensity = check_ahap(ahap, 70.0);
  ASSERT_EQ(intensity.size(), clip.amplitude.size());
  for (std::size_t i = 0; i < intensity.size(); ++i) EXPECT_NEAR(intensity[i].value, clip.amplitude[i].value, 1e-9);
  const Json haptic = JsonReader::parse(write_meta_haptic(clip));
  EXPECT_EQ(check_haptic(haptic).size(), clip.amplitude.size());
  EXPECT_EQ(haptic["metadata"]["source"].string(), clip.metadata.source);
  // The transient: a HapticTransient of intensity sqrt(0.9), sharpness sqrt(0.5); in .haptic the
  // emphasis {0.9, 0.5} of the amplitude breakpoint at 1 s, and no other.
  int ahap_transients = 0;
  for (const Json& item : ahap["Pattern"].array()) {
    if (!item.has("Event") || item["Event"]["EventType"].string() != "HapticTransient") continue;
    ++ahap_transients;
    EXPECT_EQ(item["Event"]["Time"].number(), 1.0);
    EXPECT_NEAR(event_parameter(item["Event"], "HapticIntensity"), std::sqrt(0.9), 1e-9);
    EXPECT_NEAR(event_parameter(item["Event"], "HapticSharpness"), std::sqrt(0.5), 1e-9);
  }
  EXPECT_EQ(ahap_transients, 1);
  int emphasised = 0;
  for (const Json& p : haptic["signals"]["continuous"]["envelopes"]["amplitude"].array()) {
    if (!p.has("emphasis")) continue;
    ++emphasised;
    EXPECT_EQ(p["time"].number(), 1.0);
    EXPECT_EQ(p["emphasis"]["amplitude"].number(), 0.9);
    EXPECT_EQ(p["emphasis"]["frequency"].number(), 0.5);
  }
  EXPECT_EQ(emphasised, 1);
}

// The correlation of the clip's amplitude with the drive's own RMS envelope over 10 ms windows.
double correlation_with_drive(const std::vector<float>& drive, double rate, const std::vector<ClipBreakpoint>& envelope) {
  const std::size_t window = static_cast<std::size_t>(0.01 * rate);
  std::vector<double> a, b;
  for (std::size_t first = 0; first + window <= drive.size(); first += window) {
    double sum = 0.0;
    for (std::size_t i = first; i < first + window; ++i) sum += static_cast<double>(drive[i]) * drive[i];
    a.push_back(std::sqrt(sum / static_cast<double>(window)));
    b.push_back(at(envelope, (static_cast<double>(first) + static_cast<double>(window) / 2.0) / rate));
  }
  const auto mean = [](const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); };
  const double ma = mean(a), mb = mean(b);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST(ClipExport, AGestureOverADotAndASurfaceFollowsTheDrive) {
  Image image;
  image.width_mm = 100;
  image.height_mm = 40;
  Element dot;
  dot.id = "dot";
  dot.body = Dot{20, 20, 3, 1.0};
  Element surface;
  surface.id = "surface";
  Surface s;
  s.x_mm = 50, s.y_mm = 5, s.width_mm = 40, s.height_mm = 30, s.period_mm = 1.0, s.gain = 0.6;
  surface.body = s;
  image.children = {dot, surface};
  const auto scene = compile_scene(image);
  PathSpec path;
  path.x0_mm = 5, path.y0_mm = 20, path.x1_mm = 95, path.y1_mm = 20;
  SamplingSpec sampling;
  sampling.speed_mm_per_s = 60;
  Gesture gesture;
  gesture.strokes.push_back(synthesise_stroke(path, sampling));

  const double rate = 8000.0;
  OfflineRenderOptions options;
  options.sample_rate_hz = rate;
  MemorySink memory;
  render_gesture(*scene, gesture, memory, options);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("vimg_clip_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"clip.ahap", "clip.haptic"}) {
    ClipMetadata metadata;
    metadata.editor = "vimg test";
    metadata.source = "dot_and_surface";
    ClipSink sink(dir / name, metadata);
    render_gesture(*scene, gesture, sink, options);
    ASSERT_FALSE(sink.error()) << *sink.error();
    const Json json = JsonReader::parse(read_file(dir / name));
    const double duration_s = static_cast<double>(memory.samples().size()) / rate;
    const std::vector<ClipBreakpoint> envelope =
        std::string(name) == "clip.ahap" ? check_ahap(json, duration_s) : check_haptic(json);
    const double r = correlation_with_drive(memory.samples(), rate, envelope);
    EXPECT_GE(r, 0.9) << name;
    std::printf("%s: %zu breakpoints, correlation with the drive's RMS envelope %.3f\n", name, envelope.size(), r);
    if (std::string(name) == "clip.ahap") {
      // The DOT is entered at (20 - 3 - 5) / 60 s = 0.2 s: a transient there.
      bool click = false;
      for (const Json& item : json["Pattern"].array()) {
        if (item.has("Event") && item["Event"]["EventType"].string() == "HapticTransient") {
          click = click || std::fabs(item["Event"]["Time"].number() - 0.2) < 0.01;
        }
      }
      EXPECT_TRUE(click);
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(ClipExport, VimgRenderWritesBothFormatsByExtension) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("vimg_clip_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string vimg = VIMG_BINARY_DIR "/cli/vimg";
  const std::string image = VIMG_SOURCE_DIR "/assets/examples/smiley.vimg";
  const std::string gesture = VIMG_SOURCE_DIR "/assets/gestures/smiley_eyes.csv";
  for (const char* name : {"eyes.ahap", "eyes.HAPTIC"}) {
    const std::string command = "'" + vimg + "' render '" + image + "' --gesture '" + gesture + "' --out '" + (dir / name).string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const Json json = JsonReader::parse(read_file(dir / name));
    EXPECT_TRUE(json.has(std::string(name) == "eyes.ahap" ? "Pattern" : "signals")) << name;
  }
  const std::string bad = "'" + vimg + "' render '" + image + "' --gesture '" + gesture + "' --out '" + (dir / "x.ahapx").string() + "' 2>/dev/null";
  EXPECT_EQ(WEXITSTATUS(std::system(bad.c_str())), 2);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vimg
