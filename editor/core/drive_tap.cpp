#include "editor/core/drive_tap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "player/touch_event.hpp"

namespace vimg::editor {

void DriveTap::open(double sample_rate_hz) {
  sample_rate_hz_.store(sample_rate_hz, std::memory_order_release);
  first_block_time_s_.store(std::numeric_limits<double>::quiet_NaN(), std::memory_order_release);
  was_silent_ = true;
  segment_count_.store(0, std::memory_order_release);
  samples_total_ = 0;
  output_.open(sample_rate_hz);
}

void DriveTap::write(std::span<const float> drive, double block_start_time_s) {
  if (std::isnan(first_block_time_s_.load(std::memory_order_relaxed))) {
    first_block_time_s_.store(block_start_time_s, std::memory_order_release);
  }
  const double rate = sample_rate_hz_.load(std::memory_order_relaxed);
  const std::size_t segments = segment_count_.load(std::memory_order_relaxed);
  if ((segments == 0 || std::abs(block_start_time_s - next_block_time_s_) > 0.5 / rate) && segments < kMaxSegments) {
    segment_time_s_[segments].store(block_start_time_s, std::memory_order_relaxed);
    segment_sample_[segments].store(samples_total_, std::memory_order_relaxed);
    segment_count_.store(segments + 1, std::memory_order_release);
  }
  samples_total_ += drive.size();
  next_block_time_s_ = block_start_time_s + static_cast<double>(drive.size()) / rate;
  bool silent = true;
  std::uint64_t w = written_.load(std::memory_order_relaxed);
  for (float v : drive) {
    if (v != 0.0f) silent = false;
    ring_[w % kRingSize].store(v, std::memory_order_relaxed);
    ++w;
  }
  written_.store(w, std::memory_order_release);
  if (was_silent_ && !silent) {
    const std::size_t n = latency_count_.load(std::memory_order_relaxed);
    if (n < kMaxLatencies) {
      latencies_[n].store(monotonic_s() - last_event_time_s_.load(std::memory_order_acquire),
                          std::memory_order_relaxed);
      latency_count_.store(n + 1, std::memory_order_release);
    }
  }
  was_silent_ = silent;
  output_.write(drive, block_start_time_s);
}

void DriveTap::copy_recent(std::vector<float>& out, std::size_t count) const {
  if (count > kRingSize) count = kRingSize;
  const std::uint64_t w = written_.load(std::memory_order_acquire);
  out.assign(count, 0.0f);
  const std::size_t available = w < count ? static_cast<std::size_t>(w) : count;
  for (std::size_t i = 0; i < available; ++i) {
    out[count - available + i] = ring_[(w - available + i) % kRingSize].load(std::memory_order_relaxed);
  }
}

std::uint64_t DriveTap::copy_since(std::uint64_t first, std::vector<float>& out, std::uint64_t* skipped) const {
  const std::uint64_t w = written_.load(std::memory_order_acquire);
  const std::uint64_t oldest = w > kRingSize / 2 ? w - kRingSize / 2 : 0;
  const std::uint64_t from = first > w ? w : (first < oldest ? oldest : first);
  if (skipped) *skipped = first < from ? from - first : 0;
  out.resize(static_cast<std::size_t>(w - from));
  for (std::uint64_t i = from; i < w; ++i) {
    out[static_cast<std::size_t>(i - from)] = ring_[i % kRingSize].load(std::memory_order_relaxed);
  }
  return w;
}

std::vector<double> DriveTap::latencies_s() const {
  const std::size_t n = latency_count_.load(std::memory_order_acquire);
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = latencies_[i].load(std::memory_order_relaxed);
  return out;
}

}  // namespace vimg::editor

namespace vimg::editor {

double DriveTap::output_time_s(double t) const {
  const std::size_t n = segment_count_.load(std::memory_order_acquire);
  const double rate = sample_rate_hz();
  if (n == 0 || rate <= 0) return 0.0;
  std::size_t i = 0;
  while (i + 1 < n && segment_time_s_[i + 1].load(std::memory_order_relaxed) <= t) ++i;
  double out = static_cast<double>(segment_sample_[i].load(std::memory_order_relaxed)) / rate +
               (t - segment_time_s_[i].load(std::memory_order_relaxed));
  if (i + 1 < n) {
    out = std::min(out, static_cast<double>(segment_sample_[i + 1].load(std::memory_order_relaxed)) / rate);
  }
  return out;
}

}  // namespace vimg::editor
