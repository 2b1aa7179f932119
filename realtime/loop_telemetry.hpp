#pragma once
// Timing of a periodic real-time loop (the touch renderer's blocks, the haptic loop's cycles),
// with one definition of every figure the project reports:
//   - lateness: how long after its absolute deadline a cycle woke (never negative);
//   - jitter p50 / p99: nearest-rank percentiles of lateness, the smallest value v such that at
//     least q of all cycles were at most v late, on 1 us bins (exact to 1 us up to 20 ms; later
//     cycles count in the top bin, and max_us keeps the true worst);
//   - overruns: cycles whose work finished after the next cycle's deadline;
//   - skips: times the loop gave up catching up and moved its schedule forward;
//   - rate: cycles per second between the first and the last recorded wake-up.
//
// Threads: one writer, the loop thread (record_*), which never allocates, locks or blocks;
// snapshot() from any thread (a consistent-enough view: counters are read one by one). reset()
// only while no loop writes.
#include <atomic>
#include <cstdint>
#include <memory>

namespace vimg {

struct LoopTimingStats {
  std::uint64_t cycles = 0;
  std::uint64_t overruns = 0;
  std::uint64_t skips = 0;
  double rate_hz = 0.0;
  double jitter_p50_us = 0.0;
  double jitter_p99_us = 0.0;
  double jitter_max_us = 0.0;
  double elapsed_s = 0.0;  // first to last wake-up
};

class LoopTelemetry {
 public:
  static constexpr std::size_t kBins = 20000;  // 1 us each

  LoopTelemetry();
  LoopTelemetry(const LoopTelemetry&) = delete;
  LoopTelemetry& operator=(const LoopTelemetry&) = delete;

  void reset() noexcept;

  // Loop thread, once per cycle: when it woke and the deadline it woke for (CLOCK_MONOTONIC ns).
  void record_wake(std::int64_t woke_ns, std::int64_t deadline_ns) noexcept;
  void record_overrun() noexcept { overruns_.fetch_add(1, std::memory_order_relaxed); }
  void record_skip() noexcept { skips_.fetch_add(1, std::memory_order_relaxed); }

  LoopTimingStats snapshot() const;

 private:
  std::unique_ptr<std::atomic<std::uint32_t>[]> bins_;
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> overruns_{0};
  std::atomic<std::uint64_t> skips_{0};
  std::atomic<std::int64_t> first_wake_ns_{0};
  std::atomic<std::int64_t> last_wake_ns_{0};
  std::atomic<std::int64_t> max_late_ns_{0};
};

// The nearest-rank percentile (0 < q <= 1) of a histogram of 1-unit bins: the smallest bin index
// i such that the bins 0..i hold at least ceil(q * total) counts. 0 for an empty histogram.
// Exposed so that tests check the one definition directly.
double nearest_rank_percentile(const std::uint32_t* bins, std::size_t bin_count, double q) noexcept;

}  // namespace vimg
