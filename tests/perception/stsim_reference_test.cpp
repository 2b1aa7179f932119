// ST-SIM against the reference implementation (the vibromaf package): every case of
// tests/data/stsim/cases.csv within 1e-6 (tests/data/stsim/README.md says how they were made).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fixture_signals.hpp"
#include "primitives/perception/stsim.hpp"
#include "primitives/perception/vibrotactile_threshold.hpp"

namespace vimg {
namespace {

constexpr double kTolerance = 1e-6;
const std::string kDir = std::string(VIMG_TEST_DATA_DIR) + "/stsim/";

TEST(StSimReference, EveryCaseWithinOneMillionth) {
  const auto signals = test::load_fixture_signals(kDir + "signals.csv");
  const auto cases = test::read_csv_rows(kDir + "cases.csv");
  ASSERT_GE(cases.size(), 40u);
  double worst = 0.0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.at("case"));
    const StSimFeatures distorted = analyse_stsim(signals.at(c.at("distorted")));
    const StSimFeatures reference = analyse_stsim(signals.at(c.at("reference")));
    const auto score = stsim(distorted, reference, std::stod(c.at("eta")));
    const std::string& result = c.at("result");
    if (result == "error") {
      EXPECT_FALSE(score.has_value());
      continue;
    }
    ASSERT_TRUE(score.has_value());
    if (result == "identical") {
      EXPECT_EQ(score->value, 1.0);
      continue;
    }
    const double temporal = std::stod(c.at("temporal"));
    const double spectral = std::stod(c.at("spectral"));
    EXPECT_NEAR(score->temporal, temporal, kTolerance);
    EXPECT_NEAR(score->spectral, spectral, kTolerance);
    worst = std::max({worst, std::abs(score->temporal - temporal), std::abs(score->spectral - spectral)});
    if (result == "complex") {
      EXPECT_LT(temporal, 0.0);
      EXPECT_EQ(score->value, 0.0);
    } else {
      ASSERT_EQ(result, "value");
      const double expected = std::stod(c.at("stsim"));
      EXPECT_NEAR(score->value, expected, kTolerance);
      worst = std::max(worst, std::abs(score->value - expected));
    }
  }
  RecordProperty("worst_difference", std::to_string(worst));
  std::printf("largest |ours - reference| over all cases: %.3g\n", worst);
}

TEST(StSimReference, ThresholdPerBinAsTheReferenceSamplesIt) {
  const auto rows = test::read_csv_rows(kDir + "threshold.csv");
  ASSERT_EQ(rows.size(), kStSimBlockSamples);
  const auto& ours = stsim_threshold_db_per_bin();
  for (const auto& row : rows) {
    const std::size_t k = std::stoul(row.at("bin"));
    EXPECT_NEAR(ours.at(k), std::stod(row.at("threshold_db")), 1e-12) << "bin " << k;
  }
}

}  // namespace
}  // namespace vimg
