// The level of short sounds (primitives/perception/channel_levels.hpp): independent of where a
// burst falls in time, and summed over time as the published thresholds are
// (tests/data/psychophysics/published_figures.csv): through the Pacinian channel the threshold of
// a burst falls about 3 dB per doubling of its duration up to about 1 s (Verrillo 1965); through
// the non-Pacinian channel it does not change (Gescheider 1976).
//   [calibration]   the summation's slope and limit: kPacinianSummationMs was set on Verrillo's
//                   "up to about 1 s", and energy summation is 3 dB per doubling by construction;
//                   the non-Pacinian window was chosen to sum nothing beyond 150 ms;
//   [property]      the level of a 30 ms burst anywhere in a 2 s signal (no published figure).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "primitives/perception/channel_levels.hpp"
#include "primitives/perception/discrimination_cues.hpp"
#include "published_figures.hpp"

namespace vimg {
namespace {

constexpr double kRateHz = 8000.0;

// A sine burst of `amplitude` (full scale 1) at frequency_hz, switched on at start_s for
// duration_s with raised-cosine ramps of ramp_s (0: abrupt; phase 0 at its start), in a signal of
// total_s. An abrupt onset is a click felt through the non-Pacinian channel in its own right.
std::vector<double> burst(double frequency_hz, double amplitude, double start_s, double duration_s, double total_s,
                          double ramp_s = 0.005) {
  std::vector<double> x(static_cast<std::size_t>(total_s * kRateHz), 0.0);
  const auto first = static_cast<std::size_t>(std::lround(start_s * kRateHz));
  const auto count = static_cast<std::size_t>(std::lround(duration_s * kRateHz));
  for (std::size_t n = 0; n < count && first + n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRateHz;
    const double r = ramp_s > 0.0 ? std::min({1.0, t / ramp_s, (duration_s - t) / ramp_s}) : 1.0;
    x[first + n] = amplitude * (0.5 - 0.5 * std::cos(std::numbers::pi * r)) * std::sin(2.0 * std::numbers::pi * frequency_hz * t);
  }
  return x;
}

// The felt level (before flooring at 0) of a unit burst: its threshold, in dB of amplitude re full
// scale, is minus this (the level grows as 20 log10 of the amplitude).
double unit_level_db(const DiscriminationFeatures& f) { return std::max(f.pacinian_level_db, f.non_pacinian_level_db); }

double threshold_db(double frequency_hz, double duration_s) {
  const double total_s = std::max(2.0, duration_s + 1.0);
  return -unit_level_db(analyse_discrimination(burst(frequency_hz, 1.0, 0.5, duration_s, total_s)));
}

TEST(TemporalSummation, AShortBurstReadsTheSameLevelWhereverItFalls) {
  // The old analysis read the strongest 512 ms frame on a 256 ms grid: a 30 ms burst between two
  // frame centres read up to 6 dB lower than one on a centre. Here: 97 positions 2.6 ms apart
  // across 256 ms (a frame's hop) and on, for a Pacinian and an LRA's frequency, gated abruptly as
  // a DOT's pulse is.
  for (const double f : {175.0, 250.0}) {
    double low = 1e300, high = -1e300;
    for (int i = 0; i <= 96; ++i) {
      const double start_s = 0.6 + 0.0026 * static_cast<double>(i) + 0.000125 * (i % 3);
      const double level = analyse_discrimination(burst(f, 0.5, start_s, 0.030, 2.0, 0.0)).level_db;
      low = std::min(low, level);
      high = std::max(high, level);
    }
    EXPECT_GT(low, 3.0) << f << " Hz: felt";
    EXPECT_LE(high - low, 0.5) << "[property] " << f << " Hz: a 30 ms burst's level varies with its position";
  }
}

TEST(TemporalSummation, PacinianThresholdFallsThreeDbPerDoublingUpToAboutOneSecond) {
  const test::PublishedRange slope = test::published_range("threshold_change_db_per_doubling_of_duration", 250.0);
  const test::PublishedRange limit_ms = test::published_range("temporal_summation_limit_ms", 250.0);
  ASSERT_LT(slope.low, slope.high);
  ASSERT_LT(limit_ms.low, limit_ms.high);
  for (const double f : {100.0, 250.0}) {
    // Least-squares slope of the threshold against log2(duration), from 30 ms to the limit's low end.
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, n = 0.0;
    for (double d = 0.030; d <= limit_ms.low / 1000.0 + 1e-9; d *= 2.0) {
      const double x = std::log2(d), y = threshold_db(f, d);
      std::printf("conformance,threshold_re_full_scale_db,%g,%g,%.4f,,\n", f, d * 1000.0, y);
      sx += x, sy += y, sxx += x * x, sxy += x * y, n += 1.0;
    }
    const double per_doubling = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    EXPECT_GE(per_doubling, slope.low) << "[calibration] " << f << " Hz";
    EXPECT_LE(per_doubling, slope.high) << "[calibration] " << f << " Hz";
    // Shorter bursts need more amplitude: 30 ms against the limit's low end.
    EXPECT_GT(threshold_db(f, 0.030) - threshold_db(f, limit_ms.low / 1000.0), 3.0 * std::log2(limit_ms.low / 30.0) - 1.5) << f;
    // Summation stops by the limit's high end: doubling from there changes the threshold < 1 dB.
    EXPECT_LT(std::abs(threshold_db(f, 2.0 * limit_ms.high / 1000.0) - threshold_db(f, limit_ms.high / 1000.0)), 1.0)
        << "[calibration] " << f << " Hz";
  }
}

TEST(TemporalSummation, NonPacinianThresholdDoesNotChangeWithDuration) {
  const test::PublishedRange slope = test::published_range("threshold_change_db_per_doubling_of_duration", 25.0);
  ASSERT_LT(slope.low, slope.high);
  // 25 Hz is felt through the non-Pacinian channel (its floor is below the Pacinian threshold
  // there). From 200 ms (five cycles; kNonPacinianWindowMs = 150) to 3.2 s.
  for (double d = 0.2; d < 3.0; d *= 2.0) {
    const double change = threshold_db(25.0, 2.0 * d) - threshold_db(25.0, d);
    EXPECT_GE(change, slope.low) << "[calibration] " << d * 1000.0 << " ms";
    EXPECT_LE(change, slope.high) << "[calibration] " << d * 1000.0 << " ms";
  }
  const DiscriminationFeatures f = analyse_discrimination(burst(25.0, 1.0, 0.5, 1.0, 2.0, 0.02));
  EXPECT_GT(f.non_pacinian_level_db, f.pacinian_level_db);
}

TEST(TemporalSummation, ASteadySineReadsItsLevelThroughBothChannels) {
  // 10 m/s^2 at 250 Hz moves the skin 4.05 um: 32.1 dB above the Pacinian 0.1 um, 7.9 dB below
  // the non-Pacinian 10 um.
  const DiscriminationFeatures f = analyse_discrimination(burst(250.0, 1.0, 0.0, 3.0, 3.0, 0.02));
  EXPECT_NEAR(f.pacinian_level_db, 20.0 * std::log10(10.0 / std::pow(2.0 * std::numbers::pi * 250.0, 2) / 1e-7), 0.2);
  EXPECT_NEAR(f.non_pacinian_level_db, 20.0 * std::log10(10.0 / std::pow(2.0 * std::numbers::pi * 250.0, 2) / 1e-5), 0.2);
  EXPECT_EQ(analyse_discrimination(std::vector<double>(4000, 0.0)).pacinian_level_db, detail::kSilentChannelDb);
}

}  // namespace
}  // namespace vimg
