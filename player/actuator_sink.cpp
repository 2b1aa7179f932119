#include "player/actuator_sink.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

void ActuatorSink::open(double sample_rate_hz) {
  sample_rate_hz_ = sample_rate_hz;
  chain_.emplace(params_, sample_rate_hz, signal_, equalize_);
  output_.open(sample_rate_hz);
  const auto longest = static_cast<std::size_t>(std::max(1.0, std::ceil(sample_rate_hz / 50.0)));
  buffer_.assign(std::max(longest, output_.min_block_samples()), 0.0f);
}

void ActuatorSink::write(std::span<const float> drive, double block_start_time_s) {
  if (!chain_ || chain_->is_identity()) {
    output_.write(drive, block_start_time_s);
    return;
  }
  std::size_t done = 0;
  while (done < drive.size()) {
    const std::size_t n = std::min(buffer_.size(), drive.size() - done);
    for (std::size_t i = 0; i < n; ++i) buffer_[i] = chain_->process(drive[done + i]);
    output_.write(std::span<const float>(buffer_.data(), n),
                  block_start_time_s + static_cast<double>(done) / sample_rate_hz_);
    done += n;
  }
}

}  // namespace vimg
