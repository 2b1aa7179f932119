// The one limiter: identity below the knee, bounded, monotonic, odd, smooth at the knee.
#include <gtest/gtest.h>

#include <limits>

#include "realtime/soft_limit.hpp"

namespace vimg {
namespace {

TEST(SoftLimiter, IsTheIdentityBelowTheKneeAndBoundedAbove) {
  for (double d = -0.5; d <= 0.5; d += 0.001) EXPECT_EQ(soft_limit(d), d);
  double prev = soft_limit(0.5);
  for (double d = 0.5; d < 50.0; d *= 1.01) {
    const double y = soft_limit(d);
    EXPECT_LE(y, 1.0);
    if (d < 5.0) {
      EXPECT_LT(y, 1.0);
    }
    EXPECT_GE(y, prev);  // monotonic
    EXPECT_EQ(soft_limit(-d), -y);
    prev = y;
  }
  // Slope continuous at the knee.
  EXPECT_NEAR((soft_limit(0.5 + 1e-6) - soft_limit(0.5)) / 1e-6, 1.0, 1e-4);
  EXPECT_LE(soft_limit(1e300), 1.0);
}

TEST(SoftLimiter, NanBecomesSilence) { EXPECT_EQ(soft_limit(std::numeric_limits<double>::quiet_NaN()), 0.0); }

}  // namespace
}  // namespace vimg
