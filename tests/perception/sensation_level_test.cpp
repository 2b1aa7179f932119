// Sensation level above the vibrotactile detection threshold (docs/perception.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "primitives/perception/sensation_level.hpp"
#include "primitives/perception/vibrotactile_threshold.hpp"
#include "fixture_signals.hpp"
#include "texture_signals.hpp"

namespace vimg {
namespace {

// The published threshold curve: the reference implementation's perceptual threshold (vibromaf
// `PerceptualThreshold(8000)`, tests/data/stsim/threshold.csv, produced by vibromaf itself), dB per
// DCT bin k, sampled at k * 8000 / 1023 Hz. Read here, never computed by the code under test.
const std::vector<double>& reference_threshold_db() {
  static const std::vector<double> table = [] {
    std::vector<double> t;
    for (const auto& row : test::read_csv_rows(std::string(VIMG_TEST_DATA_DIR) + "/stsim/threshold.csv")) {
      t.push_back(std::stod(row.at("threshold_db")));
    }
    return t;
  }();
  return table;
}
double reference_frequency_hz(std::size_t k) { return static_cast<double>(k) * 8000.0 / 1023.0; }
// The reference's first positive bin: from there on it holds that bin's value (docs/perception.md).
std::size_t reference_hold_bin() {
  std::size_t k = 0;
  while (!(reference_threshold_db().at(k) > 0.0)) ++k;
  return k;
}

// The peak displacement at threshold at the reference's bin k: the published curve anchored at
// 250 Hz to 0.1 um (Verrillo 1963; docs/perception.md), i.e. 0.1 um * 10^((T_k + 77) / 20).
double threshold_displacement_m(std::size_t k) { return 1e-7 * std::pow(10.0, (reference_threshold_db().at(k) + 77.0) / 20.0); }

// The full-scale amplitude (10 m/s^2, the default calibration) of a sine at the reference's bin k
// whose peak displacement is `db` above that threshold.
double amplitude_at(std::size_t k, double db) {
  const double omega = 2.0 * std::numbers::pi * reference_frequency_hz(k);
  return threshold_displacement_m(k) * omega * omega * std::pow(10.0, db / 20.0) / 10.0;
}

std::size_t band_of(double f_hz) {
  for (std::size_t b = 0; b < kSensationBands; ++b) {
    if (f_hz >= kSensationBandLowHz[b] && f_hz < kSensationBandHighHz[b]) return b;
  }
  return kSensationBands;
}

TEST(VibrotactileThreshold, IsThePublishedCurveAtItsSamplePoints) {
  // Every bin below the reference's hold, at the frequency the reference samples it at; the
  // continuous curve is held at 0 dB from its zero crossing on, where the reference holds its first
  // positive sample (0.27 dB).
  const std::size_t hold = reference_hold_bin();
  ASSERT_EQ(hold, 100u);
  for (std::size_t k = 0; k < hold; ++k) {
    EXPECT_NEAR(vibrotactile_threshold_db(reference_frequency_hz(k)), reference_threshold_db()[k], 1e-9) << "bin " << k;
    EXPECT_NEAR(threshold_peak_displacement_m(reference_frequency_hz(k)) / threshold_displacement_m(k), 1.0, 1e-9) << "bin " << k;
  }
  EXPECT_EQ(vibrotactile_threshold_db(reference_frequency_hz(hold)), 0.0);
  EXPECT_EQ(vibrotactile_threshold_db(4000.0), 0.0);
  // The curve's defining points (docs/perception.md): -77 dB at 250 Hz, -15 dB at 0 Hz.
  EXPECT_NEAR(vibrotactile_threshold_db(250.0), -77.0, 1e-12);
  EXPECT_NEAR(vibrotactile_threshold_db(0.0), -15.0, 1e-12);
  // The anchor: 0.1 um at 250 Hz (Verrillo 1963, Bolanowski et al. 1988), scaled with the calibration.
  EXPECT_NEAR(threshold_peak_displacement_m(250.0), 1e-7, 1e-19);
  LevelCalibration half;
  half.threshold_at_250hz_peak_displacement_m = 0.5e-7;
  EXPECT_NEAR(threshold_peak_displacement_m(40.0, half) / threshold_peak_displacement_m(40.0), 0.5, 1e-12);
}

TEST(SensationLevel, ASineReadsItsLevelAboveThresholdInItsBand) {
  // Sines at the reference's sample frequencies (bins 3, 4, 8, 9, 16, 18, 32, 64: 23.5 to 500.5 Hz),
  // at amplitudes computed from the published table. The 64 ms frames spread a sine over about
  // +-16 Hz (the Hann window's main lobe); where the threshold changes fast over that span the
  // level leans towards the more sensitive side. Within 0.5 dB from 60 to 250 Hz (frequencies 16 Hz
  // or more inside their band), within 4 dB below 44 Hz (one band there), within 2 dB at 500 Hz
  // (the curve rises 1.5 dB per 7.8 Hz).
  for (const std::size_t k : {3u, 4u, 8u, 9u, 16u, 18u, 32u, 64u}) {
    const double f = reference_frequency_hz(k);
    const double tolerance_db = f < 44.0 ? 4.0 : f <= 251.0 ? 0.5 : 2.0;
    for (double db : {-10.0, 0.0, 20.0}) {
      const auto x = test::partials_signal(1.0, {{amplitude_at(k, db), f}});
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

// docs/perception.md: a block is felt when a frame overlapping it has a band above threshold and
// the block is not all zeros. Four blocks of 512: a full-scale 250 Hz sine, silence, the sine again,
// then silence but for one sample of 1e-9. The frames that straddle blocks 0-1 and 2-3 are felt
// (the sine is 32 dB above threshold), so blocks 1 and 3 have a felt frame over them; block 1 is
// all zeros and is not felt, block 3 holds one nonzero sample and is.
TEST(SensationLevel, ABlockIsFeltOnlyIfNotAllZeros) {
  const auto sine = test::partials_signal(1.0, {{1.0, 250.0}});
  std::vector<double> x(4 * 512, 0.0);
  for (std::size_t n = 0; n < 512; ++n) x[n] = x[1024 + n] = sine[n];
  x[1536 + 300] = 1e-9;
  const SensationLevels levels = sensation_levels(x);
  EXPECT_EQ(levels.felt_block, (std::vector<std::uint8_t>{1, 0, 1, 1}));
  x[1536 + 300] = 0.0;
  EXPECT_EQ(sensation_levels(x).felt_block, (std::vector<std::uint8_t>{1, 0, 1, 0}));
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
