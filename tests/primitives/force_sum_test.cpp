#include "primitives/force_sum.hpp"

#include <gtest/gtest.h>

#include <random>

namespace vimg {
namespace {

TEST(ForceSum, SumsThenClampsOnceKeepingDirection) {
  ForceSum sum;
  sum.add({3.0, 0.0, 0.0});
  sum.add({0.0, 4.0, 0.0});
  const Vec3 f = sum.clamped_N(2.5);
  EXPECT_NEAR(norm(f), 2.5, 1e-12);
  EXPECT_NEAR(f.x / f.y, 3.0 / 4.0, 1e-12);
}

TEST(ForceSum, OpposingContributionsCancelBeforeTheClamp) {
  // Clamping each term first would give 1 + (-1) = 0 too, but 5 + (-4.5) = 0.5 must survive.
  ForceSum sum;
  sum.add({5.0, 0.0, 0.0});
  sum.add({-4.5, 0.0, 0.0});
  EXPECT_NEAR(sum.clamped_N(1.0).x, 0.5, 1e-12);
}

TEST(ForceSum, PropertyMagnitudeNeverExceedsLimit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int i = 0; i < 10000; ++i) {
    ForceSum sum;
    for (int k = 0; k < 5; ++k) sum.add({u(rng), u(rng), u(rng)});
    const double limit = std::abs(u(rng));
    EXPECT_LE(norm(sum.clamped_N(limit)), limit * (1.0 + 1e-12));
    if (norm(sum.unclamped_N()) <= limit) {
      EXPECT_EQ(sum.clamped_N(limit), sum.unclamped_N());
    }
  }
}

TEST(ForceSum, NonPositiveLimitGivesZero) {
  EXPECT_EQ(clamp_magnitude({1.0, 2.0, 3.0}, 0.0), Vec3{});
  EXPECT_EQ(clamp_magnitude({1.0, 2.0, 3.0}, -1.0), Vec3{});
}

}  // namespace
}  // namespace vimg
