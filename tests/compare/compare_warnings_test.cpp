// vimg compare's warnings (study/compare.hpp): a pair likely confused (p >= 0.2) and, after them,
// an image identified less than kIdentifiedTarget of the time that is in no such pair.
#include <gtest/gtest.h>

#include "study/compare.hpp"
#include "study/separate_search.hpp"

namespace vimg::study {
namespace {

const std::vector<std::string> kLabels = {"A.vimg", "B.vimg", "C.vimg", "D.vimg"};

TEST(CompareWarnings, AnImageIdentifiedBelowTheTargetWithSpreadConfusionsIsWarnedAbout) {
  // B is confused with A, C and D, each below 0.2; A and C are identified 90 % or more; D is
  // likely confused with nobody but identified 85 % of the time.
  const PerceptionMatrix p = {{0.90, 0.05, 0.03, 0.02},
                              {0.15, 0.69, 0.10, 0.06},
                              {0.02, 0.03, 0.95, 0.00},
                              {0.01, 0.04, 0.10, 0.85}};
  const std::vector<ConfusedPair> pairs = likely_confused_pairs(p);
  ASSERT_TRUE(pairs.empty());
  const std::vector<std::string> w = poorly_identified_warnings(p, pairs, kLabels);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "B.vimg: identified 69 % of the time (below 90 %), most often taken for A.vimg (p = 0.15)");
  EXPECT_EQ(w[1], "D.vimg: identified 85 % of the time (below 90 %), most often taken for C.vimg (p = 0.10)");
}

TEST(CompareWarnings, AnImageInALikelyConfusedPairIsWarnedAboutOnce) {
  const PerceptionMatrix p = {{0.5, 0.5, 0.0}, {0.5, 0.5, 0.0}, {0.0, 0.12, 0.88}};
  const std::vector<ConfusedPair> pairs = likely_confused_pairs(p);
  ASSERT_EQ(pairs.size(), 1u);
  const std::vector<std::string> w = poorly_identified_warnings(p, pairs, kLabels);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "C.vimg: identified 88 % of the time (below 90 %), most often taken for B.vimg (p = 0.12)");
}

TEST(CompareWarnings, ASetIdentifiedAtTheTargetGetsNone) {
  const double t = kIdentifiedTarget;
  const PerceptionMatrix p = {{t, 1.0 - t}, {1.0 - t, t}};
  EXPECT_TRUE(poorly_identified_warnings(p, likely_confused_pairs(p), kLabels).empty());
  EXPECT_TRUE(poorly_identified_warnings({{1.0}}, {}, kLabels).empty());
  EXPECT_TRUE(poorly_identified_warnings({}, {}, kLabels).empty());
}

}  // namespace
}  // namespace vimg::study
