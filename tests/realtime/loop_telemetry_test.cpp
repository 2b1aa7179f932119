// Loop telemetry: the one definition of percentiles, lateness, rate, overruns; the clock's
// absolute sleep; the priority report.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <thread>

#include "realtime/clock.hpp"
#include "realtime/loop_telemetry.hpp"
#include "realtime/realtime_priority.hpp"

namespace vimg {
namespace {

TEST(NearestRankPercentile, IsTheSmallestValueCoveringTheShare) {
  // 100 samples: 90 at 0 us, 9 at 5 us, 1 at 40 us.
  std::array<std::uint32_t, 50> bins{};
  bins[0] = 90;
  bins[5] = 9;
  bins[40] = 1;
  EXPECT_EQ(nearest_rank_percentile(bins.data(), bins.size(), 0.50), 0.0);
  EXPECT_EQ(nearest_rank_percentile(bins.data(), bins.size(), 0.90), 0.0);
  EXPECT_EQ(nearest_rank_percentile(bins.data(), bins.size(), 0.91), 5.0);
  EXPECT_EQ(nearest_rank_percentile(bins.data(), bins.size(), 0.99), 5.0);
  EXPECT_EQ(nearest_rank_percentile(bins.data(), bins.size(), 1.00), 40.0);
  std::array<std::uint32_t, 4> empty{};
  EXPECT_EQ(nearest_rank_percentile(empty.data(), empty.size(), 0.5), 0.0);
}

TEST(LoopTelemetry, RecordsLatenessRateAndCounters) {
  LoopTelemetry t;
  const std::int64_t period_ns = 1'000'000;  // 1 kHz
  // 1000 cycles: 980 on time, 10 late by 7 us, 10 late by 300 us; one woke early (counts as 0).
  for (int i = 0; i < 1000; ++i) {
    const std::int64_t deadline = 5'000'000'000 + i * period_ns;
    std::int64_t late = 0;
    if (i % 100 == 1) late = 7'000;
    if (i % 100 == 2) late = 300'000;
    if (i == 3) late = -5'000;
    t.record_wake(deadline + late, deadline);
  }
  t.record_overrun();
  t.record_skip();
  const LoopTimingStats s = t.snapshot();
  EXPECT_EQ(s.cycles, 1000u);
  EXPECT_EQ(s.overruns, 1u);
  EXPECT_EQ(s.skips, 1u);
  EXPECT_EQ(s.jitter_p50_us, 0.0);
  EXPECT_EQ(s.jitter_p99_us, 7.0);
  EXPECT_DOUBLE_EQ(s.jitter_max_us, 300.0);
  EXPECT_NEAR(s.rate_hz, 1000.0, 1.0);
  t.reset();
  EXPECT_EQ(t.snapshot().cycles, 0u);
  EXPECT_EQ(t.snapshot().jitter_max_us, 0.0);
}

TEST(LoopTelemetry, LatenessBeyondTheBinsIsKeptExactlyAsTheMaximum) {
  LoopTelemetry t;
  t.record_wake(1'000'000'000 + 50'000'000, 1'000'000'000);  // 50 ms late
  const LoopTimingStats s = t.snapshot();
  EXPECT_DOUBLE_EQ(s.jitter_max_us, 50'000.0);
  EXPECT_DOUBLE_EQ(s.jitter_p99_us, static_cast<double>(LoopTelemetry::kBins - 1));
}

TEST(MonotonicClock, SleepsUntilAnAbsoluteDeadlineAndNeverGoesBack) {
  const std::int64_t t0 = monotonic_ns();
  sleep_until_ns(t0 + 3'000'000);
  const std::int64_t t1 = monotonic_ns();
  EXPECT_GE(t1 - t0, 3'000'000);
  sleep_until_ns(t0);  // in the past: returns at once
  EXPECT_LT(monotonic_ns() - t1, 50'000'000);
  EXPECT_NEAR(monotonic_s(), static_cast<double>(monotonic_ns()) * 1e-9, 1e-3);
}

TEST(RealtimePriority, NothingRequestedIsReportedAsNormal) {
  const RealtimePriority p = request_realtime_priority(0);
  EXPECT_FALSE(p.granted);
  EXPECT_EQ(describe(p), "normal priority");
}

TEST(RealtimePriority, ARefusalIsReportedWithItsReasonAndTheRemedy) {
  std::string text;
  bool granted = false;
  std::thread([&] {
    const RealtimePriority p = request_realtime_priority(150);  // clamped to 99
    granted = p.granted;
    EXPECT_EQ(p.requested, 99);
    text = describe(p);
  }).join();
  if (granted) {
    EXPECT_EQ(text, "SCHED_FIFO 99");
  } else {
    EXPECT_NE(text.find("SCHED_FIFO 99 refused: "), std::string::npos) << text;
    EXPECT_NE(text.find("CAP_SYS_NICE"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace vimg
