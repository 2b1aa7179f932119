// The Shepard-Luce choice model over a similarity matrix (docs/perception.md).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "primitives/perception/predicted_confusion.hpp"

namespace vimg {
namespace {

TEST(ChoiceModel, RowsSumToOneAndFollowShepardLuce) {
  const PerceptionMatrix s = {{1.0, 0.8, 0.1}, {0.8, 1.0, 0.3}, {0.1, 0.3, 1.0}};
  const PerceptionMatrix p = predicted_confusion(s);
  for (std::size_t i = 0; i < 3; ++i) {
    double sum = 0.0;
    for (double v : p[i]) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-15);
  }
  // p(j|i) / p(i|i) = exp(-(1 - s_ij) / tau), tau = 0.1.
  EXPECT_NEAR(p[0][1] / p[0][0], std::exp(-2.0), 1e-12);
  EXPECT_NEAR(p[0][2] / p[0][0], std::exp(-9.0), 1e-12);
  EXPECT_NEAR(p[1][2] / p[1][1], std::exp(-7.0), 1e-12);
}

TEST(ChoiceModel, TauSetsHowFastConfusionFalls) {
  const PerceptionMatrix s = {{1.0, 0.9}, {0.9, 1.0}};
  EXPECT_LT(predicted_confusion(s, {0.02, 0.2})[0][1], predicted_confusion(s, {0.1, 0.2})[0][1]);
  EXPECT_NEAR(predicted_confusion(s, {0.1, 0.2})[0][1], std::exp(-1.0) / (1.0 + std::exp(-1.0)), 1e-12);
  // tau not > 0 counts as the default.
  EXPECT_EQ(predicted_confusion(s, {0.0, 0.2}), predicted_confusion(s));
}

TEST(ChoiceModel, OutOfRangeAndNaNSimilarities) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PerceptionMatrix p = predicted_confusion({{1.0, nan, 1.5}, {nan, 1.0, -3.0}, {1.5, -3.0, 1.0}});
  EXPECT_DOUBLE_EQ(p[0][0], p[0][2]);  // 1.5 counts as 1
  EXPECT_NEAR(p[0][1] / p[0][0], std::exp(-10.0), 1e-12);  // NaN counts as 0
  EXPECT_NEAR(p[1][2] / p[1][1], std::exp(-10.0), 1e-12);  // -3 counts as 0
  EXPECT_TRUE(predicted_confusion({}).empty());
  EXPECT_EQ(predicted_confusion({{0.0}}), PerceptionMatrix{{1.0}});
}

TEST(ChoiceModel, NoUnderflowWhenEverythingIsFar) {
  // Even with a tiny tau the row is the nearest choice, never 0/0.
  const PerceptionMatrix p = predicted_confusion({{0.0, 0.0}, {0.0, 0.0}}, {1e-6, 0.2});
  EXPECT_DOUBLE_EQ(p[0][0], 0.5);
  EXPECT_DOUBLE_EQ(p[0][1], 0.5);
}

TEST(LikelyConfused, ThresholdAndOrder) {
  const PerceptionMatrix p = {{0.6, 0.25, 0.15}, {0.1, 0.5, 0.4}, {0.19, 0.05, 0.76}};
  const auto pairs = likely_confused_pairs(p);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].a, 1u);
  EXPECT_EQ(pairs[0].b, 2u);
  EXPECT_DOUBLE_EQ(pairs[0].p, 0.4);
  EXPECT_EQ(pairs[1].a, 0u);
  EXPECT_EQ(pairs[1].b, 1u);
  EXPECT_DOUBLE_EQ(pairs[1].p, 0.25);
  EXPECT_EQ(likely_confused_pairs(p, {0.1, 0.5}).size(), 0u);
  EXPECT_EQ(likely_confused_pairs(p, {0.1, 0.1}).size(), 3u);
}

}  // namespace
}  // namespace vimg
