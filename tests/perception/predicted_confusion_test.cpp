// The warning over a predicted confusion matrix (docs/perception.md).
#include <gtest/gtest.h>

#include "primitives/perception/predicted_confusion.hpp"

namespace vimg {
namespace {

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
  EXPECT_EQ(likely_confused_pairs(p, {0.5}).size(), 0u);
  EXPECT_EQ(likely_confused_pairs(p, {0.1}).size(), 3u);
}

}  // namespace
}  // namespace vimg
