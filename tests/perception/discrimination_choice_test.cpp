// The choice rule of primitives/perception/discrimination_choice.hpp against its equations:
//   D = sqrt(sum_c (w_c d_c)^2),  p(j | i) = (1 - lapse) exp(-D_ij / T) / sum_k exp(-D_ik / T) + lapse / n.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "primitives/perception/discrimination_choice.hpp"

namespace vimg {
namespace {

CueDistances along(std::size_t cue, double jnd) {
  CueDistances d{};
  d[cue] = jnd;
  return d;
}

TEST(DiscriminationChoice, OneJndApartAloneIsConfusedAQuarterOfTheTime) {
  for (std::size_t cue = 0; cue < kCueCount; ++cue) {
    const CueMatrix m = {{CueDistances{}, along(cue, 1.0)}, {along(cue, 1.0), CueDistances{}}};
    const PerceptionMatrix p = discrimination_confusion(m);
    EXPECT_NEAR(p[0][1], 0.25, 1e-12) << cue_name(cue);
    EXPECT_NEAR(p[1][0], 0.25, 1e-12);
    EXPECT_NEAR(p[0][0], 0.75, 1e-12);
  }
  EXPECT_NEAR(two_alternative_confusion(0.0), 0.5, 1e-12);
  EXPECT_NEAR(two_alternative_confusion(2.0), 1.0 / (1.0 + 9.0), 1e-12);
}

TEST(DiscriminationChoice, CuesCombineAsAWeightedEuclideanDistance) {
  ASSERT_GE(kCueCount, 2u);
  CueDistances d{};
  d[0] = 3.0;
  d[1] = 4.0;
  EXPECT_NEAR(combined_distance_jnd(d), 5.0, 1e-12);
  DiscriminationConstants k;
  k.cue_weight[0] = 0.0;
  k.cue_weight[1] = 0.5;
  EXPECT_NEAR(combined_distance_jnd(d, k), 2.0, 1e-12);
  k.cue_weight[1] = std::nan("");
  d[0] = -1.0;
  EXPECT_EQ(combined_distance_jnd(d, k), 0.0);
}

TEST(DiscriminationChoice, RowsFollowTheEquationWithLapseAndSumToOne) {
  const CueMatrix m = {{CueDistances{}, along(0, 1.0), along(0, 3.0)},
                       {along(0, 1.0), CueDistances{}, along(0, 2.0)},
                       {along(0, 3.0), along(0, 2.0), CueDistances{}}};
  DiscriminationConstants k;
  k.temperature_jnd = 0.7;
  k.lapse_rate = 0.12;
  const PerceptionMatrix p = discrimination_confusion(m, k);
  const double distance[3][3] = {{0, 1, 3}, {1, 0, 2}, {3, 2, 0}};
  for (int i = 0; i < 3; ++i) {
    double total = 0.0;
    for (int j = 0; j < 3; ++j) total += std::exp(-distance[i][j] / 0.7);
    double row = 0.0;
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(p[i][j], 0.88 * std::exp(-distance[i][j] / 0.7) / total + 0.04, 1e-12);
      row += p[i][j];
    }
    EXPECT_NEAR(row, 1.0, 1e-12);
  }
}

TEST(DiscriminationChoice, FarApartSetsNeitherUnderflowNorLeaveTheDiagonal) {
  const CueMatrix m = {{CueDistances{}, along(2, 1e6)}, {along(2, 1e6), CueDistances{}}};
  const PerceptionMatrix p = discrimination_confusion(m);
  EXPECT_EQ(p[0][0], 1.0);
  EXPECT_EQ(p[0][1], 0.0);
  DiscriminationConstants guesses;
  guesses.lapse_rate = 7.0;
  const PerceptionMatrix q = discrimination_confusion(m, guesses);  // clamped to 1: every answer a guess
  EXPECT_NEAR(q[0][0], 0.5, 1e-12);
  // No default stands in for an invalid temperature (a fallback to 1 / ln 3 would give 0.5 here).
  for (const double t : {-1.0, 0.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    guesses.temperature_jnd = t;
    EXPECT_TRUE(std::isnan(discrimination_confusion(m, guesses)[0][0])) << t;
  }
  EXPECT_TRUE(discrimination_confusion({}).empty());
}

}  // namespace
}  // namespace vimg
