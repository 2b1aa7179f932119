// The vibrotactile detection threshold and the level above it (docs/perception.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "primitives/perception/discrimination_cues.hpp"
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

// The model's Pacinian threshold as peak displacement at the reference's bin k, computed here from
// its stated form (docs/perception.md): anchored at 250 Hz to 0.1 um (Verrillo 1963); below 250 Hz
// rising 13 dB per octave (the published 12 dB/octave, read 10-14); above 250 Hz the reference
// curve's rise, 0.1 um * 10^((T_k + 77) / 20).
double threshold_displacement_m(std::size_t k) {
  const double f = reference_frequency_hz(k);
  if (f <= 250.0) return 1e-7 * std::pow(10.0, 13.0 * std::log2(250.0 / f) / 20.0);
  return 1e-7 * std::pow(10.0, (reference_threshold_db().at(k) + 77.0) / 20.0);
}

// The full-scale amplitude (10 m/s^2, the default calibration) of a sine at the reference's bin k
// whose peak displacement is `db` above that threshold.
double amplitude_at(std::size_t k, double db) {
  const double omega = 2.0 * std::numbers::pi * reference_frequency_hz(k);
  return threshold_displacement_m(k) * omega * omega * std::pow(10.0, db / 20.0) / 10.0;
}

TEST(VibrotactileThreshold, IsThePublishedCurveAtItsSamplePoints) {
  // Every bin below the reference's hold, at the frequency the reference samples it at; the
  // continuous curve is held at 0 dB from its zero crossing on, where the reference holds its first
  // positive sample (0.27 dB).
  const std::size_t hold = reference_hold_bin();
  ASSERT_EQ(hold, 100u);
  for (std::size_t k = 0; k < hold; ++k) {
    EXPECT_NEAR(vibrotactile_threshold_db(reference_frequency_hz(k)), reference_threshold_db()[k], 1e-9) << "bin " << k;
  }
  EXPECT_EQ(vibrotactile_threshold_db(reference_frequency_hz(hold)), 0.0);
  EXPECT_EQ(vibrotactile_threshold_db(4000.0), 0.0);
  // The curve's defining points (docs/perception.md): -77 dB at 250 Hz, -15 dB at 0 Hz.
  EXPECT_NEAR(vibrotactile_threshold_db(250.0), -77.0, 1e-12);
  EXPECT_NEAR(vibrotactile_threshold_db(0.0), -15.0, 1e-12);
}

TEST(PacinianThreshold, RisesThirteenDbPerOctaveBelow250HzAndAsTheReferenceCurveAbove) {
  for (std::size_t k = 1; k < reference_hold_bin(); ++k) {
    EXPECT_NEAR(threshold_peak_displacement_m(reference_frequency_hz(k)) / threshold_displacement_m(k), 1.0, 1e-9) << "bin " << k;
  }
  // The slope itself, octave by octave (40, 80 and 125 Hz against twice their frequency).
  for (double f : {40.0, 80.0, 125.0}) {
    EXPECT_NEAR(20.0 * std::log10(threshold_peak_displacement_m(f) / threshold_peak_displacement_m(2.0 * f)), 13.0, 1e-9) << f;
  }
  // Continuous at the minimum, and rising on both sides of it.
  EXPECT_NEAR(threshold_peak_displacement_m(249.999) / threshold_peak_displacement_m(250.001), 1.0, 1e-4);
  EXPECT_GT(threshold_peak_displacement_m(200.0), threshold_peak_displacement_m(250.0));
  EXPECT_GT(threshold_peak_displacement_m(300.0), threshold_peak_displacement_m(250.0));
  // The anchor: 0.1 um at 250 Hz (Verrillo 1963, Bolanowski et al. 1988), scaled with the calibration.
  EXPECT_NEAR(threshold_peak_displacement_m(250.0), 1e-7, 1e-19);
  LevelCalibration half;
  half.threshold_at_250hz_peak_displacement_m = 0.5e-7;
  EXPECT_NEAR(threshold_peak_displacement_m(40.0, half) / threshold_peak_displacement_m(40.0), 0.5, 1e-12);
  // Outside the curve's domain (0 Hz, negative, NaN) it is finite: the value at its lowest frequency.
  for (double f : {0.0, -5.0, std::nan("")}) {
    EXPECT_EQ(threshold_peak_displacement_m(f), threshold_peak_displacement_m(kLowestModelledThresholdHz)) << f;
  }
}

TEST(SensationLevel, ASineReadsItsLevelAboveThreshold) {
  // Sines at the reference's sample frequencies from 62.6 to 500.5 Hz (bins 8 to 64, where the
  // Pacinian curve is the skin's threshold), at amplitudes computed from its stated form: the
  // discrimination model's level (its strongest 512 ms frame) reads the level above threshold,
  // within 0.5 dB up to 250 Hz and 2 dB at 500 Hz (the curve rises 1.5 dB per 7.8 Hz there), and
  // 0 below threshold (nothing felt).
  for (const std::size_t k : {8u, 9u, 16u, 18u, 32u, 64u}) {
    const double f = reference_frequency_hz(k);
    const double tolerance_db = f <= 251.0 ? 0.5 : 2.0;
    for (double db : {-10.0, 5.0, 20.0}) {
      auto x = test::partials_signal(2.0, {{amplitude_at(k, db), f}});
      // Raised-cosine onset and offset of 20 ms (an abrupt one is a click, felt in its own right).
      for (std::size_t n = 0; n < 160; ++n) {
        const double ramp = 0.5 - 0.5 * std::cos(std::numbers::pi * static_cast<double>(n) / 160.0);
        x[n] *= ramp;
        x[x.size() - 1 - n] *= ramp;
      }
      EXPECT_NEAR(analyse_discrimination(x).level_db, std::max(db, 0.0), tolerance_db) << f << " Hz, " << db << " dB";
    }
  }
}

TEST(SensationLevel, FullScaleAt250HzWithTheDefaultCalibration) {
  // 10 m/s^2 at 250 Hz is 4.05 um, 32.1 dB above 0.1 um.
  EXPECT_NEAR(analyse_discrimination(test::partials_signal(1.0, {{1.0, 250.0}})).level_db, 32.1, 0.3);
  // Four times the acceleration: 12 dB more.
  LevelCalibration stronger;
  stronger.full_scale_peak_acceleration_mps2 = 40.0;
  EXPECT_NEAR(analyse_discrimination(test::partials_signal(1.0, {{1.0, 250.0}}), stronger).level_db, 32.1 + 12.04, 0.3);
}

TEST(SensationLevel, SilenceIsFeltNowhere) {
  const DiscriminationFeatures silent = analyse_discrimination(test::silence(1.5));
  EXPECT_EQ(silent.level_db, 0.0);
  EXPECT_EQ(analyse_discrimination(std::vector<double>{}).level_db, 0.0);
}

}  // namespace
}  // namespace vimg
