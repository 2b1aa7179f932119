#pragma once
// A haptic clip for phones and controllers (docs/export.md): an amplitude envelope, a frequency
// track and transients, as breakpoints in time, and its writers:
//   - Apple Core Haptics AHAP (`.ahap`): Version 1.0, a Pattern of HapticContinuous events (at most
//     30 s each) with HapticIntensityControl and HapticSharpnessControl ParameterCurves of at most
//     16 control points (times relative to the curve), and a HapticTransient per transient;
//   - Meta Haptics Studio / Lofelt v1 (`.haptic`): version 1.0.0, metadata (editor, author,
//     source, project, tags, description), and
//     signals.continuous.envelopes.amplitude [{time, amplitude[, emphasis]}] and frequency
//     [{time, frequency}].
// Pure text: the caller writes the file (atomically).
#include <string>
#include <vector>

namespace vimg {

struct ClipBreakpoint {
  double time_s = 0.0;  // from the start of the clip, ascending
  double value = 0.0;   // in [0, 1]
};

struct ClipTransient {
  double time_s = 0.0;
  double amplitude = 0.0;  // [0, 1]
  double frequency = 0.0;  // normalised, [0, 1]
};

struct ClipMetadata {
  std::string editor;       // e.g. "vimg 0.4.0"
  std::string author;       // the image's author (.haptic only: AHAP has no such key)
  std::string source;       // the image the clip was rendered from (its file name: clip_metadata.hpp)
  std::string project;
  std::string description;
  std::vector<std::string> tags;
};

struct HapticClip {
  double duration_s = 0.0;
  std::vector<ClipBreakpoint> amplitude;  // the envelope of the drive, 1 = full scale
  std::vector<ClipBreakpoint> frequency;  // normalised frequency (clip_frequency_from_hz)
  std::vector<ClipTransient> transients;  // clicks (a DOT being entered)
  ClipMetadata metadata;
};

// The normalised frequency of both formats: 0 at kClipLowHz, 1 at kClipHighHz, logarithmic
// between (clamped outside).
inline constexpr double kClipLowHz = 40.0;
inline constexpr double kClipHighHz = 500.0;
double clip_frequency_from_hz(double frequency_hz);

// Core Haptics limits: control points per parameter curve, and the longest continuous event.
inline constexpr std::size_t kAhapMaxCurvePoints = 16;
inline constexpr double kAhapMaxContinuousS = 30.0;

std::string write_ahap(const HapticClip& clip);
std::string write_meta_haptic(const HapticClip& clip);

}  // namespace vimg
