#pragma once
// Decimates a drive stream to an envelope device's update rate (DRV2605L RTP writes, HID
// triggers) and times each update on the device clock: the first block after start() anchors
// stream time to the clock, so updates keep the stream's spacing whatever the block timing.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "player/render_defaults.hpp"
#include "realtime/clock.hpp"

namespace vimg {

class UpdateSchedule {
 public:
  void start(double sample_rate_hz, double update_rate_hz) {
    sample_rate_hz_ = sample_rate_hz;
    samples_per_update_ = std::max<std::int64_t>(1, std::llround(sample_rate_hz / update_rate_hz));
    sample_counter_ = 0;
    anchored_ = false;
  }

  // Calls on_sample(x) for every sample of the block, and on_update(time_us) after every
  // samples_per_update-th sample, with that sample's time on the clock.
  template <class OnSample, class OnUpdate>
  void feed(std::span<const float> drive, double block_start_time_s, const Clock& clock, OnSample&& on_sample,
            OnUpdate&& on_update) {
    if (!anchored_) {
      epoch_us_ = clock.now_us() - std::llround(block_start_time_s * 1e6);
      anchored_ = true;
    }
    for (std::size_t i = 0; i < drive.size(); ++i) {
      on_sample(drive[i]);
      if (++sample_counter_ >= samples_per_update_) {
        sample_counter_ = 0;
        const double time_s = block_start_time_s + static_cast<double>(i + 1) / sample_rate_hz_;
        on_update(epoch_us_ + std::llround(time_s * 1e6));
      }
    }
  }

 private:
  double sample_rate_hz_ = kDefaultRenderRateHz;
  std::int64_t samples_per_update_ = 1;
  std::int64_t sample_counter_ = 0;
  std::int64_t epoch_us_ = 0;
  bool anchored_ = false;
};

}  // namespace vimg
