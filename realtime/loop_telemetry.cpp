#include "realtime/loop_telemetry.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vimg {

LoopTelemetry::LoopTelemetry() : bins_(std::make_unique<std::atomic<std::uint32_t>[]>(kBins)) { reset(); }

void LoopTelemetry::reset() noexcept {
  for (std::size_t i = 0; i < kBins; ++i) bins_[i].store(0, std::memory_order_relaxed);
  cycles_.store(0, std::memory_order_relaxed);
  overruns_.store(0, std::memory_order_relaxed);
  skips_.store(0, std::memory_order_relaxed);
  first_wake_ns_.store(0, std::memory_order_relaxed);
  last_wake_ns_.store(0, std::memory_order_relaxed);
  max_late_ns_.store(0, std::memory_order_release);
}

void LoopTelemetry::record_wake(std::int64_t woke_ns, std::int64_t deadline_ns) noexcept {
  const std::int64_t late_ns = std::max<std::int64_t>(0, woke_ns - deadline_ns);
  const auto bin = std::min<std::size_t>(kBins - 1, static_cast<std::size_t>(late_ns / 1000));
  bins_[bin].fetch_add(1, std::memory_order_relaxed);
  if (late_ns > max_late_ns_.load(std::memory_order_relaxed)) max_late_ns_.store(late_ns, std::memory_order_relaxed);
  if (cycles_.load(std::memory_order_relaxed) == 0) first_wake_ns_.store(woke_ns, std::memory_order_relaxed);
  last_wake_ns_.store(woke_ns, std::memory_order_relaxed);
  cycles_.fetch_add(1, std::memory_order_release);
}

double nearest_rank_percentile(const std::uint32_t* bins, std::size_t bin_count, double q) noexcept {
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < bin_count; ++i) total += bins[i];
  if (total == 0) return 0.0;
  const auto rank = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(total))));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < bin_count; ++i) {
    seen += bins[i];
    if (seen >= rank) return static_cast<double>(i);
  }
  return static_cast<double>(bin_count - 1);
}

LoopTimingStats LoopTelemetry::snapshot() const {
  LoopTimingStats s;
  s.cycles = cycles_.load(std::memory_order_acquire);
  s.overruns = overruns_.load(std::memory_order_relaxed);
  s.skips = skips_.load(std::memory_order_relaxed);
  s.jitter_max_us = static_cast<double>(max_late_ns_.load(std::memory_order_relaxed)) * 1e-3;
  const std::int64_t first = first_wake_ns_.load(std::memory_order_relaxed);
  const std::int64_t last = last_wake_ns_.load(std::memory_order_relaxed);
  s.elapsed_s = s.cycles > 1 ? static_cast<double>(last - first) * 1e-9 : 0.0;
  s.rate_hz = s.elapsed_s > 0.0 ? static_cast<double>(s.cycles - 1) / s.elapsed_s : 0.0;
  // Copy the bins once (this may run on a display thread; the copy is the only allocation).
  static thread_local std::vector<std::uint32_t> copy;
  copy.resize(kBins);
  for (std::size_t i = 0; i < kBins; ++i) copy[i] = bins_[i].load(std::memory_order_relaxed);
  s.jitter_p50_us = nearest_rank_percentile(copy.data(), kBins, 0.50);
  s.jitter_p99_us = nearest_rank_percentile(copy.data(), kBins, 0.99);
  // The top bin holds everything above 20 ms: the worst case is known exactly.
  s.jitter_p50_us = std::min(s.jitter_p50_us, s.jitter_max_us);
  s.jitter_p99_us = std::min(s.jitter_p99_us, s.jitter_max_us);
  return s;
}

}  // namespace vimg
