#include "storage/export/haptic_clip.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "storage/export/json_writer.hpp"

namespace vimg {

double clip_frequency_from_hz(double frequency_hz) {
  if (!(frequency_hz > kClipLowHz)) return 0.0;
  return std::clamp(std::log(frequency_hz / kClipLowHz) / std::log(kClipHighHz / kClipLowHz), 0.0, 1.0);
}

namespace {

double unit(double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; }

void parameter(JsonWriter& w, const char* id, double value) {
  w.begin_object();
  w.key("ParameterID");
  w.string(id);
  w.key("ParameterValue");
  w.number(value);
  w.end_object();
}

// One AHAP event: {"Event": {Time, EventType, [EventDuration], EventParameters: intensity, sharpness}}.
void event(JsonWriter& w, double time_s, const char* type, std::optional<double> duration_s, double intensity,
           double sharpness) {
  w.begin_object();
  w.key("Event");
  w.begin_object();
  w.key("Time");
  w.number(time_s);
  w.key("EventType");
  w.string(type);
  if (duration_s) {
    w.key("EventDuration");
    w.number(*duration_s);
  }
  w.key("EventParameters");
  w.begin_array();
  parameter(w, "HapticIntensity", intensity);
  parameter(w, "HapticSharpness", sharpness);
  w.end_array();
  w.end_object();
  w.end_object();
}

// Curves of at most kAhapMaxCurvePoints points; each after the first starts with the last point
// of the one before, so that the value is continuous. Values go through `map` (a perceptual
// square root, as Meta's converter from .haptic to AHAP does).
void curves(JsonWriter& w, const char* id, const std::vector<ClipBreakpoint>& points) {
  for (std::size_t first = 0; first + 1 < points.size() || (first == 0 && points.size() == 1);) {
    const std::size_t last = std::min(points.size() - 1, first + kAhapMaxCurvePoints - 1);
    const double start = points[first].time_s;
    w.begin_object();
    w.key("ParameterCurve");
    w.begin_object();
    w.key("ParameterID");
    w.string(id);
    w.key("Time");
    w.number(start);
    w.key("ParameterCurveControlPoints");
    w.begin_array();
    for (std::size_t i = first; i <= last; ++i) {
      w.begin_object();
      w.key("Time");
      w.number(points[i].time_s - start);
      w.key("ParameterValue");
      w.number(std::sqrt(unit(points[i].value)));
      w.end_object();
    }
    w.end_array();
    w.end_object();
    w.end_object();
    if (last == first) break;
    first = last;
  }
}

}  // namespace

std::string write_ahap(const HapticClip& clip) {
  JsonWriter w;
  w.begin_object();
  w.key("Version");
  w.number_text("1.0");  // as Apple's AHAP samples write it
  w.key("Metadata");
  w.begin_object();
  w.key("Project");
  w.string(clip.metadata.project);
  w.key("Created");
  w.string(clip.metadata.editor);
  w.key("Description");
  w.string(clip.metadata.description.empty() ? "rendered from " + clip.metadata.source : clip.metadata.description);
  w.end_object();
  w.key("Pattern");
  w.begin_array();
  // The continuous events carry intensity 1 and sharpness 0; the curves set both over time.
  for (double t = 0.0; t < clip.duration_s; t += kAhapMaxContinuousS) {
    event(w, t, "HapticContinuous", std::min(kAhapMaxContinuousS, clip.duration_s - t), 1.0, 0.0);
  }
  curves(w, "HapticIntensityControl", clip.amplitude);
  curves(w, "HapticSharpnessControl", clip.frequency);
  for (const ClipTransient& t : clip.transients) {
    event(w, t.time_s, "HapticTransient", std::nullopt, std::sqrt(unit(t.amplitude)), std::sqrt(unit(t.frequency)));
  }
  w.end_array();
  w.end_object();
  return w.take();
}

std::string write_meta_haptic(const HapticClip& clip) {
  JsonWriter w;
  w.begin_object();
  w.key("version");
  w.begin_object();
  w.key("major");
  w.integer(1);
  w.key("minor");
  w.integer(0);
  w.key("patch");
  w.integer(0);
  w.end_object();
  w.key("metadata");
  w.begin_object();
  w.key("editor");
  w.string(clip.metadata.editor);
  w.key("author");
  w.string(clip.metadata.author);
  w.key("source");
  w.string(clip.metadata.source);
  w.key("project");
  w.string(clip.metadata.project);
  w.key("tags");
  w.begin_array();
  for (const std::string& tag : clip.metadata.tags) w.string(tag);
  w.end_array();
  w.key("description");
  w.string(clip.metadata.description);
  w.end_object();
  w.key("signals");
  w.begin_object();
  w.key("continuous");
  w.begin_object();
  w.key("envelopes");
  w.begin_object();
  w.key("amplitude");
  w.begin_array();
  std::size_t next_transient = 0;
  for (const ClipBreakpoint& p : clip.amplitude) {
    w.begin_object();
    w.key("time");
    w.number(p.time_s);
    w.key("amplitude");
    w.number(unit(p.value));
    // A transient becomes the emphasis of the breakpoint at its time.
    while (next_transient < clip.transients.size() && clip.transients[next_transient].time_s < p.time_s) ++next_transient;
    if (next_transient < clip.transients.size() && clip.transients[next_transient].time_s == p.time_s) {
      w.key("emphasis");
      w.begin_object();
      w.key("amplitude");
      w.number(unit(clip.transients[next_transient].amplitude));
      w.key("frequency");
      w.number(unit(clip.transients[next_transient].frequency));
      w.end_object();
    }
    w.end_object();
  }
  w.end_array();
  w.key("frequency");
  w.begin_array();
  for (const ClipBreakpoint& p : clip.frequency) {
    w.begin_object();
    w.key("time");
    w.number(p.time_s);
    w.key("frequency");
    w.number(unit(p.value));
    w.end_object();
  }
  w.end_array();
  w.end_object();
  w.end_object();
  w.end_object();
  w.end_object();
  return w.take();
}

}  // namespace vimg
