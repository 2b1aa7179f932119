#pragma once
// The classic stimuli of vibrotactile psychophysics at 8 kHz: sines at a sensation level above the
// published detection threshold (published_figures.hpp: never the model's own), raised-cosine onset
// and offset ramps, with or without a silent gap, steady or as a rhythm of bursts.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "primitives/perception/discrimination_cues.hpp"
#include "published_figures.hpp"

namespace vimg::test {

// Strong enough that every stimulus of the suite stays within |x| <= 1.
inline LevelCalibration strong_actuator() {
  LevelCalibration c;
  c.full_scale_peak_acceleration_mps2 = 200.0;
  return c;
}

struct Tone {
  double frequency_hz = 250.0;
  double sensation_level_db = 30.0;  // above published_threshold_peak_displacement_m
  double duration_s = 1.0;
  double ramp_s = 0.02;              // raised cosine
  double gap_ms = 0.0;               // silent gap in the middle (abrupt edges)
  double phase_rad = 0.0;
  // The threshold the sensation level is above: the published one (the middle of its band), or the
  // model's own (skin_threshold_peak_displacement_m), for pairs of different frequencies that must
  // be at equal sensation level as the experiments set them per participant: the published table
  // has no figure above 300 Hz and its band is not a curve.
  bool above_model_threshold = false;
};

inline std::vector<double> render_tone(const Tone& t, const LevelCalibration& c = strong_actuator()) {
  const double omega = 2.0 * std::numbers::pi * t.frequency_hz;
  const double threshold_m = t.above_model_threshold ? skin_threshold_peak_displacement_m(t.frequency_hz, c)
                                                     : published_threshold_peak_displacement_m(t.frequency_hz);
  const double displacement_m = threshold_m * std::pow(10.0, t.sensation_level_db / 20.0);
  const double amplitude = displacement_m * omega * omega / c.full_scale_peak_acceleration_mps2;
  const auto n = static_cast<std::size_t>(t.duration_s * 8000.0);
  const double gap_begin_s = t.duration_s / 2.0 - t.gap_ms / 2000.0;
  const double gap_end_s = t.duration_s / 2.0 + t.gap_ms / 2000.0;
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / 8000.0;
    if (s >= gap_begin_s && s < gap_end_s) continue;
    const double ramp = std::min({1.0, s / t.ramp_s, (t.duration_s - s) / t.ramp_s});
    const double gain = 0.5 - 0.5 * std::cos(std::numbers::pi * ramp);
    x[i] = gain * amplitude * std::sin(omega * s + t.phase_rad);
  }
  return x;
}

// A rhythm: the tone's duration cut into `pulses` bursts of the tone (each with its ramps) and
// pulses - 1 silences as long as a burst; 1 pulse is the steady tone.
inline std::vector<double> render_pulses(const Tone& t, int pulses, const LevelCalibration& c = strong_actuator()) {
  Tone burst = t;
  burst.duration_s = t.duration_s / static_cast<double>(2 * pulses - 1);
  burst.ramp_s = std::min(t.ramp_s, burst.duration_s / 4.0);
  const std::vector<double> one = render_tone(burst, c);
  std::vector<double> x(static_cast<std::size_t>(t.duration_s * 8000.0), 0.0);
  for (int k = 0; k < pulses; ++k) {
    const auto start = static_cast<std::size_t>(2.0 * k * burst.duration_s * 8000.0);
    for (std::size_t i = 0; i < one.size() && start + i < x.size(); ++i) x[start + i] = one[i];
  }
  return x;
}

}  // namespace vimg::test
