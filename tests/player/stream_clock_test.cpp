// StreamClock: stream times are exact sample counts; the event offset follows the device, with a
// lag of drift * tau, whatever the queue and the device's buffer size.
#include "player/stream_clock.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vimg {
namespace {

constexpr double kRate = 8000.0;
constexpr std::uint64_t kBlock = 8;

// The render loop against a device that plays `speed` * kRate samples per second, takes
// `buffer` samples per callback and keeps `queue` samples queued: the block that starts at
// sample n is rendered when the device has room for it. Returns the largest mapping error
// |to_stream_s(now) - time of the block rendered now| after `settle_s`, over `duration_s`.
double worst_mapping_error_s(double speed, std::uint64_t queue, std::uint64_t buffer, double duration_s,
                             double settle_s, double start_s = 1000.0) {
  StreamClock clock(kRate);
  clock.start(start_s);
  double worst = 0.0;
  for (std::uint64_t n = 0; static_cast<double>(n) / kRate < duration_s; n += kBlock) {
    // Room for the block once the device has taken, a whole buffer at a time, all but `queue`.
    const std::uint64_t must_have_played = n + kBlock > queue ? n + kBlock - queue : 0;
    const std::uint64_t callbacks = (must_have_played + buffer - 1) / buffer;
    const double now_s = start_s + static_cast<double>(callbacks * buffer) / (kRate * speed);
    clock.observe(n, now_s);
    if (now_s - start_s >= settle_s) {
      worst = std::max(worst, std::fabs(clock.to_stream_s(now_s) - clock.sample_time_s(n)));
    }
  }
  return worst;
}

TEST(StreamClock, StreamTimeIsTheSampleCountOverTheRate) {
  StreamClock clock(kRate);
  clock.start(50.0);
  EXPECT_DOUBLE_EQ(clock.sample_time_s(0), 50.0);
  EXPECT_DOUBLE_EQ(clock.sample_time_s(8000 * 3 + 4), 50.0 + 3.0 + 4.0 / kRate);
  EXPECT_DOUBLE_EQ(clock.offset_s(), 0.0);
  clock.observe(0, 49.99);
  EXPECT_NEAR(clock.offset_s(), 0.01, 1e-12) << "the first observation is taken as it is";
  EXPECT_NEAR(clock.to_monotonic_s(clock.to_stream_s(7.0)), 7.0, 1e-12);
}

TEST(StreamClock, ADeviceOnTheSameClockMapsEventsOntoTheBlockRenderedNow) {
  // 64-sample queue, 64-sample callbacks: the raw offset saws by one buffer (8 ms); the mapping
  // keeps its mean, within the buffer.
  EXPECT_LT(worst_mapping_error_s(1.0, 64, 64, 5.0, 1.0), 0.008);
  // Sample by sample (a FIFO that takes one sample at a time): nearly exact.
  EXPECT_LT(worst_mapping_error_s(1.0, 64, 1, 5.0, 1.0), 0.0005);
}

TEST(StreamClock, ADriftingDeviceClockLagsByDriftTimesTheTimeConstant) {
  const double tau = StreamClock::kDefaultTimeConstant_s;
  for (double speed : {0.99, 1.01}) {
    const double drift = std::fabs(1.0 / speed - 1.0);
    const double worst = worst_mapping_error_s(speed, 64, 1, 60.0, 2.0);
    EXPECT_LT(worst, 1.2 * drift * tau) << speed;
    EXPECT_GT(worst, 0.5 * drift * tau) << speed << ": the lag of a first-order follower";
  }
}

TEST(StreamClock, TheErrorStaysBoundedHoweverLongTheStreamPlays) {
  // An hour at 1 % off: an unanchored stream clock would be 36 s away; this one stays within
  // drift * tau plus a device buffer.
  const double worst = worst_mapping_error_s(0.99, 256, 64, 3600.0, 2.0);
  EXPECT_LT(worst, 0.0101 * StreamClock::kDefaultTimeConstant_s * 1.2 + 0.008);
}

}  // namespace
}  // namespace vimg
