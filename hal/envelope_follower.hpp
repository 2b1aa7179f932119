#pragma once
// Turns a normalized drive signal into what an amplitude-envelope device (DRV2605L RTP) can play:
// its envelope and its carrier frequency.
// Envelope: the peak of |x| over the last one to two periods of the nominal carrier (two windows of
// one period each, so the ripple of a carrier never reaches the envelope); it follows a rising peak
// at once and a falling one exponentially with release_time_s.
// Frequency: the interval between positive-going zero crossings (hysteresis 0.02), 0 when the last
// crossing is older than 50 ms.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vimg {

class EnvelopeFollower {
 public:
  void configure(double sample_rate_hz, double nominal_frequency_hz, double release_time_s) {
    sample_period_s_ = 1.0 / sample_rate_hz;
    hold_samples_ = static_cast<std::int64_t>(std::ceil(sample_rate_hz / nominal_frequency_hz));
    decay_per_sample_ = std::exp(-sample_period_s_ / release_time_s);
    stale_samples_ = static_cast<std::int64_t>(0.05 * sample_rate_hz);
    reset();
  }

  void reset() {
    envelope_ = 0.0;
    window_count_ = 0;
    current_window_max_ = 0.0;
    previous_window_max_ = 0.0;
    sample_index_ = 0;
    last_rise_index_ = -1;
    frequency_hz_ = 0.0;
    above_ = false;
  }

  void push(float sample) {
    const double magnitude = std::fabs(static_cast<double>(sample));
    current_window_max_ = std::max(current_window_max_, magnitude);
    const double target = std::max(current_window_max_, previous_window_max_);
    if (++window_count_ >= hold_samples_) {
      previous_window_max_ = current_window_max_;
      current_window_max_ = 0.0;
      window_count_ = 0;
    }
    envelope_ = target >= envelope_ ? target : target + (envelope_ - target) * decay_per_sample_;
    track_crossings(static_cast<double>(sample));
    ++sample_index_;
  }

  double envelope() const { return envelope_ > 1.0 ? 1.0 : envelope_; }
  double frequency_hz() const {
    return (last_rise_index_ >= 0 && sample_index_ - last_rise_index_ <= stale_samples_) ? frequency_hz_ : 0.0;
  }

 private:
  void track_crossings(double sample) {
    constexpr double kHysteresis = 0.02;
    if (!above_ && sample > kHysteresis) {
      above_ = true;
      if (last_rise_index_ >= 0) {
        const auto interval = sample_index_ - last_rise_index_;
        frequency_hz_ = 1.0 / (static_cast<double>(interval) * sample_period_s_);
      }
      last_rise_index_ = sample_index_;
    } else if (above_ && sample < -kHysteresis) {
      above_ = false;
    }
  }

  double sample_period_s_ = 1.0 / 8000.0;
  std::int64_t hold_samples_ = 23;
  double decay_per_sample_ = 0.99;
  std::int64_t stale_samples_ = 400;
  double envelope_ = 0.0;
  std::int64_t window_count_ = 0;
  double current_window_max_ = 0.0;
  double previous_window_max_ = 0.0;
  std::int64_t sample_index_ = 0;
  std::int64_t last_rise_index_ = -1;
  double frequency_hz_ = 0.0;
  bool above_ = false;
};

}  // namespace vimg
