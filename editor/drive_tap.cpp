#include "editor/drive_tap.hpp"

#include <cmath>
#include <limits>

#include "player/touch_event.hpp"

namespace vimg::editor {

void DriveTap::open(double sample_rate_hz) {
  sample_rate_hz_.store(sample_rate_hz, std::memory_order_release);
  first_block_time_s_.store(std::numeric_limits<double>::quiet_NaN(), std::memory_order_release);
  was_silent_ = true;
  output_.open(sample_rate_hz);
}

void DriveTap::write(std::span<const float> drive, double block_start_time_s) {
  if (std::isnan(first_block_time_s_.load(std::memory_order_relaxed))) {
    first_block_time_s_.store(block_start_time_s, std::memory_order_release);
  }
  bool silent = true;
  std::size_t w = written_.load(std::memory_order_relaxed);
  for (float v : drive) {
    if (v != 0.0f) silent = false;
    ring_[w % kRingSize].store(v, std::memory_order_relaxed);
    ++w;
  }
  written_.store(w, std::memory_order_release);
  if (was_silent_ && !silent) {
    const std::size_t n = latency_count_.load(std::memory_order_relaxed);
    if (n < kMaxLatencies) {
      latencies_[n].store(monotonic_time_s() - last_event_time_s_.load(std::memory_order_acquire),
                          std::memory_order_relaxed);
      latency_count_.store(n + 1, std::memory_order_release);
    }
  }
  was_silent_ = silent;
  output_.write(drive, block_start_time_s);
}

void DriveTap::copy_recent(std::vector<float>& out, std::size_t count) const {
  if (count > kRingSize) count = kRingSize;
  const std::size_t w = written_.load(std::memory_order_acquire);
  out.assign(count, 0.0f);
  const std::size_t available = w < count ? w : count;
  for (std::size_t i = 0; i < available; ++i) {
    out[count - available + i] = ring_[(w - available + i) % kRingSize].load(std::memory_order_relaxed);
  }
}

std::vector<double> DriveTap::latencies_s() const {
  const std::size_t n = latency_count_.load(std::memory_order_acquire);
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = latencies_[i].load(std::memory_order_relaxed);
  return out;
}

}  // namespace vimg::editor
