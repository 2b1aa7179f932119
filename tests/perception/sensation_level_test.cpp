// Sensation level above the vibrotactile detection threshold (docs/perception.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "primitives/perception/sensation_level.hpp"
#include "primitives/perception/vibrotactile_threshold.hpp"
#include "texture_signals.hpp"

namespace vimg {
namespace {

// The full-scale amplitude of a sine at f whose peak displacement is `db` above threshold.
double amplitude_at(double f_hz, double db, const LevelCalibration& c = {}) {
  const double omega = 2.0 * std::numbers::pi * f_hz;
  const double acceleration = threshold_peak_displacement_m(f_hz, c) * omega * omega * std::pow(10.0, db / 20.0);
  return acceleration / c.full_scale_peak_acceleration_mps2;
}

std::size_t band_of(double f_hz) {
  for (std::size_t b = 0; b < kSensationBands; ++b) {
    if (f_hz >= kSensationBandLowHz[b] && f_hz < kSensationBandHighHz[b]) return b;
  }
  return kSensationBands;
}

TEST(VibrotactileThreshold, UShapedLowestAt250Hz) {
  EXPECT_NEAR(vibrotactile_threshold_db(250.0), -77.0, 1e-12);
  EXPECT_NEAR(vibrotactile_threshold_db(0.0), -15.0, 1e-12);
  double previous = vibrotactile_threshold_db(0.0);
  for (double f = 5.0; f <= 250.0; f += 5.0) {  // falling towards 250 Hz
    EXPECT_LT(vibrotactile_threshold_db(f), previous) << f;
    previous = vibrotactile_threshold_db(f);
  }
  for (double f = 255.0; f < 780.0; f += 5.0) {  // rising above it
    EXPECT_GT(vibrotactile_threshold_db(f), previous) << f;
    previous = vibrotactile_threshold_db(f);
  }
  // Steep below 100 Hz: 40 Hz needs some 39 dB more than 250 Hz, 100 Hz some 17 dB.
  EXPECT_GT(vibrotactile_threshold_db(40.0) - vibrotactile_threshold_db(250.0), 35.0);
  EXPECT_GT(vibrotactile_threshold_db(100.0) - vibrotactile_threshold_db(250.0), 12.0);
  EXPECT_EQ(vibrotactile_threshold_db(1000.0), 0.0);
  EXPECT_EQ(vibrotactile_threshold_db(4000.0), 0.0);
}

TEST(SensationLevel, ASineReadsItsLevelAboveThresholdInItsBand) {
  // The 64 ms frames spread a sine over about +-16 Hz (the Hann window's main lobe); where the
  // threshold changes fast over that span the level leans towards the more sensitive side. Within
  // 0.5 dB from 60 to 250 Hz (frequencies 16 Hz or more inside their band), within 4 dB below
  // 44 Hz (one band there), within 2 dB at 500 Hz (the curve rises 1.5 dB per 7.8 Hz).
  for (double f : {23.4375, 31.25, 62.5, 70.3125, 125.0, 140.625, 250.0, 500.0}) {
    const double tolerance_db = f < 44.0 ? 4.0 : f <= 250.0 ? 0.5 : 2.0;
    for (double db : {-10.0, 0.0, 20.0}) {
      const auto x = test::partials_signal(1.0, {{amplitude_at(f, db), f}});
      const SensationLevels levels = sensation_levels(x);
      EXPECT_NEAR(levels.peak_level_db[band_of(f)], db, tolerance_db) << f << " Hz, " << db << " dB";
      EXPECT_NEAR(levels.felt_db(band_of(f)), std::max(db, 0.0), tolerance_db);
    }
  }
}

TEST(SensationLevel, FullScaleAt250HzWithTheDefaultCalibration) {
  // 10 m/s^2 at 250 Hz is 4.05 um, 32.1 dB above 0.1 um.
  const SensationLevels levels = sensation_levels(test::partials_signal(1.0, {{1.0, 250.0}}));
  EXPECT_NEAR(levels.peak_level_db[band_of(250.0)], 32.1, 0.3);
  EXPECT_NEAR(levels.max_felt_db(), 32.1, 0.3);
}

TEST(SensationLevel, CalibrationShiftsEveryBand) {
  const auto x = test::surface_signal(2.0);
  const SensationLevels base = sensation_levels(x);
  LevelCalibration stronger;
  stronger.full_scale_peak_acceleration_mps2 *= 2.0;
  const SensationLevels shifted = sensation_levels(x, stronger);
  for (std::size_t b = 0; b < kSensationBands; ++b) {
    if (base.peak_level_db[b] > kSilentLevelDb + 10.0) {
      EXPECT_NEAR(shifted.peak_level_db[b] - base.peak_level_db[b], 20.0 * std::log10(2.0), 1e-9);
    }
  }
}

TEST(SensationLevel, SilenceIsFeltNowhere) {
  const SensationLevels levels = sensation_levels(test::silence(1.5));
  for (double db : levels.peak_level_db) EXPECT_EQ(db, kSilentLevelDb);
  EXPECT_EQ(levels.max_felt_db(), 0.0);
  EXPECT_EQ(levels.felt_block.size(), 24u);  // 12000 samples: 23 blocks and a zero-padded one
  for (auto felt : levels.felt_block) EXPECT_EQ(felt, 0);
  EXPECT_TRUE(sensation_levels(std::vector<double>{}).felt_block.empty());
}

TEST(SensationLevel, FeltBlocksFollowTheSignal) {
  const SensationLevels levels = sensation_levels(test::dot_signal(4.0));
  std::size_t felt = 0;
  for (auto f : levels.felt_block) felt += f;
  EXPECT_GT(felt, 4u);
  EXPECT_LT(felt, levels.felt_block.size() / 2);
}

}  // namespace
}  // namespace vimg
