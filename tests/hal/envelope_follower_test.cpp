#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hal/envelope_follower.hpp"

namespace vimg {
namespace {

TEST(EnvelopeFollower, SteadyCarrierGivesItsAmplitudeWithoutRipple) {
  for (const double frequency : {175.0, 200.0, 250.0, 400.0}) {
    for (const double amplitude : {0.2, 0.5, 1.0}) {
      EnvelopeFollower follower;
      follower.configure(8000.0, 175.0, 0.01);
      double low = 1.0, high = 0.0;
      for (int i = 0; i < 8000; ++i) {
        follower.push(static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * frequency * i / 8000.0)));
        if (i > 200) {
          low = std::min(low, follower.envelope());
          high = std::max(high, follower.envelope());
        }
      }
      EXPECT_NEAR(low, amplitude, 0.01 * amplitude) << frequency << " Hz";
      EXPECT_NEAR(high, amplitude, 0.001);
      EXPECT_NEAR(follower.frequency_hz(), frequency, frequency * 0.03);
    }
  }
}

TEST(EnvelopeFollower, DecaysAfterTheDriveStopsAndClampsToOne) {
  EnvelopeFollower follower;
  follower.configure(8000.0, 175.0, 0.005);
  for (int i = 0; i < 400; ++i) follower.push(3.0f);
  EXPECT_DOUBLE_EQ(follower.envelope(), 1.0);
  // Two carrier periods (11.4 ms) plus five release constants (25 ms): below 1 %.
  for (int i = 0; i < 300; ++i) follower.push(0.0f);
  EXPECT_LT(follower.envelope(), 0.01);
  for (int i = 0; i < 400; ++i) follower.push(0.0f);
  EXPECT_DOUBLE_EQ(follower.frequency_hz(), 0.0);  // stale
}

}  // namespace
}  // namespace vimg
