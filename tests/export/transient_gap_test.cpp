// docs/export.md: a transient comes "at least 50 ms after the previous one". Three clicks (5 ms
// bursts of a 175 Hz sine, each after silence) 45 ms and then 55 ms apart: the second, 45 ms after
// the first, is no transient; the third, 100 ms after the first transient (55 ms after the second
// click), is one. Without the gap rule all three are onsets, so the rule alone removes the second.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "player/clip_export/drive_envelope.hpp"

namespace vimg {
namespace {

constexpr double kRateHz = 8000.0;

// 0.4 s of silence with a 5 ms burst (one analysis window) starting at each of `starts_s`.
std::vector<float> clicks(const std::vector<double>& starts_s) {
  std::vector<float> drive(static_cast<std::size_t>(0.4 * kRateHz), 0.0f);
  for (double start_s : starts_s) {
    const auto first = static_cast<std::size_t>(std::lround(start_s * kRateHz));
    for (std::size_t i = 0; i < 40; ++i) {
      drive[first + i] = static_cast<float>(0.9 * std::sin(2 * std::numbers::pi * 175.0 * static_cast<double>(i) / kRateHz));
    }
  }
  return drive;
}

std::vector<double> transient_times(const std::vector<float>& drive, DriveEnvelopeOptions options = {}) {
  DriveEnvelope envelope(kRateHz, options);
  envelope.add(drive);
  std::vector<double> times;
  for (const ClipTransient& t : envelope.clip().transients) times.push_back(t.time_s);
  return times;
}

TEST(TransientGap, TheDocumentedGapIsFiftyMilliseconds) { EXPECT_EQ(DriveEnvelopeOptions{}.transient_gap_s, 0.05); }

TEST(TransientGap, AClickWithin50MsOfTheLastTransientIsNoneAndOneAfterIs) {
  const std::vector<float> drive = clicks({0.100, 0.145, 0.200});
  DriveEnvelopeOptions no_gap;
  no_gap.transient_gap_s = 0.0;
  const std::vector<double> all = transient_times(drive, no_gap);
  ASSERT_EQ(all.size(), 3u);  // each click is an onset by level and rise
  const std::vector<double> kept = transient_times(drive);
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0], all[0]);
  EXPECT_EQ(kept[1], all[2]);
  EXPECT_NEAR(kept[1] - kept[0], 0.100, 1e-9);
  EXPECT_NEAR(all[1] - all[0], 0.045, 1e-9);
  for (std::size_t i = 1; i < kept.size(); ++i) EXPECT_GE(kept[i] - kept[i - 1], 0.05);
}

}  // namespace
}  // namespace vimg
