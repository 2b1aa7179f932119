#pragma once
// The rendered drive as a haptic clip (docs/export.md): an amplitude envelope (RMS over short
// windows, scaled so that a full-scale sine is 1), a frequency track (upward zero crossings,
// interpolated between samples) and transients (sudden onsets, such as a DOT being entered),
// then breakpoints merged wherever they lie within a tolerance of a straight line.
//
// Threads: not real-time. A DriveEnvelope grows with the clip (one window per 5 ms); feed it from
// an offline render, or through an SPSC ring from a real-time thread.
#include <cstddef>
#include <span>
#include <vector>

#include "storage/export/haptic_clip.hpp"

namespace vimg {

struct EnvelopeWindow {
  double time_s = 0.0;       // the window's centre
  double amplitude = 0.0;    // sqrt(2) * RMS, clamped to [0, 1]
  double frequency_hz = 0.0; // from zero crossings; the previous window's when it had none
};

struct DriveEnvelopeOptions {
  double window_s = 0.005;           // amplitude and frequency resolution
  double merge_tolerance = 0.02;     // breakpoints merged where linear to within this (2 % of full scale)
  double transient_level = 0.2;      // an onset reaches at least this amplitude ...
  double transient_rise = 4.0;       // ... this many times the mean of the windows before it
  double transient_gap_s = 0.05;     // and comes at least this long after the previous one
};

class DriveEnvelope {
 public:
  DriveEnvelope(double sample_rate_hz, DriveEnvelopeOptions options = {});

  // Samples in [-1, 1], in order.
  void add(std::span<const float> drive);

  // The windows so far, the last partial one included.
  std::vector<EnvelopeWindow> windows() const;
  double duration_s() const { return static_cast<double>(samples_) / rate_hz_; }

  // The clip: merged breakpoints from time 0 to the end, and the transients (each with a
  // breakpoint at its time). Metadata is left for the caller.
  HapticClip clip() const;

 private:
  void close_window();

  double rate_hz_;
  DriveEnvelopeOptions options_;
  std::size_t window_samples_;
  std::vector<EnvelopeWindow> windows_;
  double sum_squares_ = 0.0;
  std::size_t in_window_ = 0;
  double period_sum_ = 0.0;   // periods ending in this window, in samples
  std::size_t periods_ = 0;
  double last_frequency_hz_ = 0.0;
  std::size_t samples_ = 0;
  float previous_ = 0.0f;
  double last_crossing_ = -1.0;  // sample position of the last upward crossing; < 0: none yet
};

// Breakpoints kept so that every dropped one lies within `tolerance` of the straight line
// between its kept neighbours; indices in `keep` are always kept. Times ascending.
std::vector<ClipBreakpoint> merge_linear(const std::vector<ClipBreakpoint>& points, double tolerance,
                                         const std::vector<std::size_t>& keep = {});

}  // namespace vimg
