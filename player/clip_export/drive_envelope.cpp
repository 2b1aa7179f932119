#include "player/clip_export/drive_envelope.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

namespace {
constexpr double kMinCarrierHz = 10.0;
constexpr double kMaxCarrierHz = 4000.0;
}  // namespace

DriveEnvelope::DriveEnvelope(double sample_rate_hz, DriveEnvelopeOptions options)
    : rate_hz_(sample_rate_hz),
      options_(options),
      window_samples_(std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(options.window_s * sample_rate_hz)))) {}

void DriveEnvelope::add(std::span<const float> drive) {
  for (const float x : drive) {
    sum_squares_ += static_cast<double>(x) * x;
    if (previous_ < 0.0f && x >= 0.0f) {
      const double position = static_cast<double>(samples_) - 1.0 + previous_ / (previous_ - x);
      if (last_crossing_ >= 0.0) {
        const double period = position - last_crossing_;
        const double f = rate_hz_ / period;
        if (f >= kMinCarrierHz && f <= kMaxCarrierHz) {
          period_sum_ += period;
          ++periods_;
        }
      }
      last_crossing_ = position;
    }
    previous_ = x;
    ++samples_;
    if (++in_window_ == window_samples_) close_window();
  }
}

void DriveEnvelope::close_window() {
  EnvelopeWindow w;
  const std::size_t first = samples_ - in_window_;
  w.time_s = (static_cast<double>(first) + static_cast<double>(in_window_) / 2.0) / rate_hz_;
  w.amplitude = std::clamp(std::sqrt(2.0 * sum_squares_ / static_cast<double>(in_window_)), 0.0, 1.0);
  if (periods_ > 0) last_frequency_hz_ = rate_hz_ * static_cast<double>(periods_) / period_sum_;
  w.frequency_hz = last_frequency_hz_;
  windows_.push_back(w);
  sum_squares_ = 0.0;
  in_window_ = 0;
  period_sum_ = 0.0;
  periods_ = 0;
}

std::vector<EnvelopeWindow> DriveEnvelope::windows() const {
  DriveEnvelope copy = *this;
  if (copy.in_window_ > 0) copy.close_window();
  return std::move(copy.windows_);
}

std::vector<ClipBreakpoint> merge_linear(const std::vector<ClipBreakpoint>& points, double tolerance,
                                         const std::vector<std::size_t>& keep) {
  if (points.size() <= 2) return points;
  std::vector<bool> must(points.size(), false);
  for (const std::size_t k : keep) {
    if (k < must.size()) must[k] = true;
  }
  std::vector<ClipBreakpoint> out = {points.front()};
  std::size_t anchor = 0;
  std::size_t end = 1;
  // Extend the segment anchor -> end while every point between stays within the tolerance.
  while (end + 1 < points.size()) {
    const std::size_t candidate = end + 1;
    bool fits = !must[end];
    const ClipBreakpoint& a = points[anchor];
    const ClipBreakpoint& b = points[candidate];
    for (std::size_t i = anchor + 1; fits && i < candidate; ++i) {
      const double t = (points[i].time_s - a.time_s) / (b.time_s - a.time_s);
      fits = std::fabs(a.value + t * (b.value - a.value) - points[i].value) <= tolerance;
    }
    if (!fits) {
      out.push_back(points[end]);
      anchor = end;
    }
    end = candidate;
  }
  out.push_back(points.back());
  return out;
}

HapticClip DriveEnvelope::clip() const {
  HapticClip clip;
  clip.duration_s = duration_s();
  std::vector<EnvelopeWindow> ws = windows();
  if (ws.empty()) return clip;
  // Before the first measured period the frequency is unknown: it takes the first one measured.
  const auto known = std::find_if(ws.begin(), ws.end(), [](const EnvelopeWindow& w) { return w.frequency_hz > 0.0; });
  if (known != ws.end()) {
    for (auto it = ws.begin(); it != known; ++it) it->frequency_hz = known->frequency_hz;
  }
  // Breakpoints: time 0, every window centre, the end.
  std::vector<ClipBreakpoint> amplitude, frequency;
  amplitude.push_back({0.0, ws.front().amplitude});
  frequency.push_back({0.0, clip_frequency_from_hz(ws.front().frequency_hz)});
  std::vector<std::size_t> keep;
  double mean_before = 0.0;
  double last_transient_s = -1e9;
  for (std::size_t i = 0; i < ws.size(); ++i) {
    const EnvelopeWindow& w = ws[i];
    // An onset: loud now, quiet in the 4 windows before, not right after another onset.
    if (i > 0 && w.amplitude >= options_.transient_level && w.amplitude >= options_.transient_rise * (mean_before + 0.01) &&
        w.time_s - last_transient_s >= options_.transient_gap_s) {
      // An onset window rarely holds a whole period: the frequency of the window after it.
      const double f_hz = i + 1 < ws.size() ? ws[i + 1].frequency_hz : w.frequency_hz;
      clip.transients.push_back({w.time_s, w.amplitude, clip_frequency_from_hz(f_hz)});
      keep.push_back(amplitude.size());
      last_transient_s = w.time_s;
    }
    amplitude.push_back({w.time_s, w.amplitude});
    frequency.push_back({w.time_s, clip_frequency_from_hz(w.frequency_hz)});
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t k = i + 1 >= 4 ? i + 1 - 4 : 0; k <= i; ++k, ++n) sum += ws[k].amplitude;
    mean_before = sum / static_cast<double>(n);
  }
  if (clip.duration_s > amplitude.back().time_s) {
    amplitude.push_back({clip.duration_s, ws.back().amplitude});
    frequency.push_back({clip.duration_s, clip_frequency_from_hz(ws.back().frequency_hz)});
  }
  clip.amplitude = merge_linear(amplitude, options_.merge_tolerance, keep);
  clip.frequency = merge_linear(frequency, options_.merge_tolerance);
  return clip;
}

}  // namespace vimg
