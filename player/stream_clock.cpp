#include "player/stream_clock.hpp"

#include <algorithm>

namespace vimg {

StreamClock::StreamClock(double sample_rate_hz, double time_constant_s)
    : sample_rate_hz_(sample_rate_hz), time_constant_s_(time_constant_s) {}

void StreamClock::start(double start_s) {
  start_s_ = start_s;
  offset_s_ = 0.0;
  last_sample_ = 0;
  observations_ = 0;
}

void StreamClock::observe(std::uint64_t sample, double now_s) {
  const double raw_s = sample_time_s(sample) - now_s;
  const double step_s = static_cast<double>(sample - std::min(sample, last_sample_)) / sample_rate_hz_;
  const double mean_weight = 1.0 / static_cast<double>(observations_ + 1);
  const double weight = std::min(1.0, std::max(mean_weight, step_s / time_constant_s_));
  offset_s_ += weight * (raw_s - offset_s_);
  last_sample_ = sample;
  ++observations_;
}

}  // namespace vimg
