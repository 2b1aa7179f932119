// The discrimination model (primitives/perception/discrimination_cues.hpp + the choice rule with its
// default constants) against published vibrotactile psychophysics
// (tests/data/psychophysics/published_figures.csv, README.md there): it renders the classic
// stimuli at sensation levels above the published threshold (never the model's own), two at a
// time, and predicts how often a two-alternative trial confuses them. Every check says which kind
// it is (docs/perception.md, "Held against the published figures"):
//   [calibration]    a constant of the model was set on this figure, so the check tests the
//                    implementation, not a prediction;
//   [out of sample]  no constant was set on it.
//   - the model's JND (the difference confused in 25 % of two-alternative trials) falls within the
//     published range for the stimulus' frequency and sensation level [calibration];
//   - a pair as far apart as the middle of the published range is confused 18-40 % [calibration];
//   - well below a JND (5 % of frequency, 0.5 dB, a 2 ms gap) near chance (>= 0.4), several JNDs
//     apart (an octave, 10 dB, a 30 ms gap) rarely (<= 0.05) [out of sample];
//   - the threshold: a sine 3 dB below the published band is confused with silence half the time,
//     one 10 dB above it rarely [calibration at 250 Hz and up to 40 Hz, out of sample between];
//     the curve's shape against the published slope [out of sample].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "tests/perception/fixture_signals.hpp"
#include "tests/perception/tone_signals.hpp"

namespace vimg {
namespace {

using test::render_tone;
using test::strong_actuator;
using test::Tone;

using Range = test::PublishedRange;
constexpr const char* kCalibration = "[calibration] ";
constexpr const char* kOutOfSample = "[out of sample] ";

// The union of the published ranges of `quantity` whose frequency and sensation-level ranges hold
// the stimulus' (the data file's sensation-level columns decide which rows apply).
Range published(const std::string& quantity, double frequency_hz, double sensation_level_db) {
  const Range r = test::published_range(quantity, frequency_hz, sensation_level_db);
  EXPECT_LT(r.low, r.high) << quantity << " at " << frequency_hz << " Hz, " << sensation_level_db << " dB SL: no published row";
  return r;
}

DiscriminationFeatures features(const Tone& t) { return analyse_discrimination(render_tone(t), strong_actuator()); }

double confusion(const DiscriminationFeatures& a, const Tone& b) {
  return two_alternative_confusion(combined_distance_jnd(cue_distances(a, features(b))));
}

double confusion(const Tone& a, const Tone& b) { return confusion(features(a), b); }

// The difference x in [low, high] at which `p(x)`, falling, crosses 0.25 (bisection).
double jnd(const std::function<double(double)>& p, double low, double high) {
  for (int i = 0; i < 14; ++i) {  // the range / 16384: far finer than the published ranges
    const double mid = 0.5 * (low + high);
    (p(mid) > 0.25 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

constexpr double kFrequenciesHz[] = {25.0, 40.0, 50.0, 80.0, 100.0, 150.0, 200.0, 250.0, 300.0};

// One line per measured JND on the test's output, for scripts/plot_perception_conformance.py:
// conformance,QUANTITY,FREQUENCY_HZ,SENSATION_LEVEL_DB,MODEL,PUBLISHED_LOW,PUBLISHED_HIGH
void report(const char* quantity, double frequency_hz, double sl_db, double model, const Range& r) {
  std::printf("conformance,%s,%g,%g,%.4f,%g,%g\n", quantity, frequency_hz, sl_db, model, r.low, r.high);
}

// The model's JND of `quantity` for the differences p(x) falls in the published range; at the
// range's middle the confusion is 18-40 %; `below` a JND near chance, `far` rarely.
struct Differences {
  double search_high = 0.0;  // the JND is sought in [0, search_high]
  double below = 0.0;        // well below a JND: confused >= 40 %
  double far = 0.0;          // several JNDs: confused <= 5 %
};

void expect_published_jnd(const char* quantity, double f, double sl, const std::function<double(double)>& p,
                          const Differences& x) {
  const Range r = published(quantity, f, sl);
  const double model = jnd(p, 0.0, x.search_high);
  report(quantity, f, sl, model, r);
  EXPECT_GE(model, r.low) << kCalibration << quantity << ", " << f << " Hz at " << sl << " dB SL";
  EXPECT_LE(model, r.high) << kCalibration << quantity << ", " << f << " Hz at " << sl << " dB SL";
  const double at_middle = p(r.middle());
  EXPECT_GE(at_middle, 0.18) << kCalibration << quantity << ", " << f << " Hz";
  EXPECT_LE(at_middle, 0.40) << kCalibration << quantity << ", " << f << " Hz";
  EXPECT_GE(p(x.below), 0.40) << kOutOfSample << quantity << ", " << f << " Hz, " << x.below << " apart";
  EXPECT_LE(p(x.far), 0.05) << kOutOfSample << quantity << ", " << f << " Hz, " << x.far << " apart";
}

void expect_published_frequency_jnd(double sl) {
  for (double f : kFrequenciesHz) {
    // At equal sensation level through the model's own threshold (Tone::above_model_threshold).
    Tone base{f, sl};
    base.above_model_threshold = true;
    const DiscriminationFeatures reference = features(base);
    const auto p = [&](double fraction) {
      Tone other = base;
      other.frequency_hz = f * (1.0 + fraction);
      return confusion(reference, other);
    };
    expect_published_jnd("frequency_weber_fraction", f, sl, p, {1.0, 0.05, 1.0});  // 5 %, an octave
  }
}

void expect_published_amplitude_jnd(double sl) {
  for (double f : kFrequenciesHz) {
    const DiscriminationFeatures reference = features(Tone{f, sl});
    const auto p = [&](double step_db) { return confusion(reference, Tone{f, sl + step_db}); };
    expect_published_jnd("amplitude_jnd_db", f, sl, p, {10.0, 0.5, 10.0});  // 0.5 dB, 10 dB
  }
}

TEST(DiscriminationConformance, FrequencyWeberFractionIsThePublishedOneAt20DbSl) { expect_published_frequency_jnd(20.0); }
// Israr et al. measured at 20 and 35 dB SL: the stimuli are at those levels above the published threshold.
TEST(DiscriminationConformance, FrequencyWeberFractionIsThePublishedOneAt35DbSl) { expect_published_frequency_jnd(35.0); }
TEST(DiscriminationConformance, AmplitudeJndIsThePublishedOneAt20DbSl) { expect_published_amplitude_jnd(20.0); }
TEST(DiscriminationConformance, AmplitudeJndIsThePublishedOneAt35DbSl) { expect_published_amplitude_jnd(35.0); }

TEST(DiscriminationConformance, GapDetectionIsThePublishedOne) {
  for (double sl : {30.0, 40.0}) {
    const Tone steady{250.0, sl};
    const DiscriminationFeatures reference = features(steady);
    const auto p = [&](double gap_ms) {
      Tone gapped = steady;
      gapped.gap_ms = gap_ms;
      return confusion(reference, gapped);
    };
    expect_published_jnd("gap_detection_ms", 250.0, sl, p, {30.0, 2.0, 30.0});  // 2 ms, 30 ms
  }
}

// A sine of peak displacement displacement_m at f (1 s, 20 ms ramps) against silence.
double against_silence(double f, double displacement_m) {
  const LevelCalibration c = strong_actuator();
  const double omega = 2.0 * std::numbers::pi * f;
  Tone t{f, 0.0};
  std::vector<double> x = render_tone(t, c);
  const double gain = displacement_m / test::published_threshold_peak_displacement_m(f);  // t is at 0 dB SL
  for (double& v : x) v *= gain;
  EXPECT_LE(displacement_m * omega * omega / c.full_scale_peak_acceleration_mps2, 1.0);
  const DiscriminationFeatures tone = analyse_discrimination(x, c);
  const DiscriminationFeatures none = analyse_discrimination(std::vector<double>(8000, 0.0), c);
  return two_alternative_confusion(combined_distance_jnd(cue_distances(tone, none)));
}

constexpr double kThresholdFrequenciesHz[] = {10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0,
                                              100.0, 125.0, 150.0, 200.0, 250.0, 300.0};

// The anchor (250-300 Hz) and the floor (up to 40 Hz) were set on these rows; between them the
// curve's shape is ST-SIM's, not set on the published slope.
const char* threshold_kind(double f) { return f <= 40.0 || f >= 250.0 ? kCalibration : kOutOfSample; }

TEST(DiscriminationConformance, ThresholdLiesInThePublishedBandAtEveryFrequency) {
  for (const double f : kThresholdFrequenciesHz) {
    const Range band = test::published_threshold_band_m(f);
    const double model_m = skin_threshold_peak_displacement_m(f);
    std::printf("conformance,threshold_peak_displacement_um,%g,,%.4g,%.4g,%.4g\n", f, model_m * 1e6, band.low * 1e6, band.high * 1e6);
    // Felt or not, by the model's whole analysis: 3 dB below the band, 10 dB above it.
    EXPECT_GE(against_silence(f, band.low * std::pow(10.0, -3.0 / 20.0)), 0.45) << threshold_kind(f) << f << " Hz, 3 dB below the published band";
    EXPECT_LE(against_silence(f, band.high * std::pow(10.0, 10.0 / 20.0)), 0.05) << threshold_kind(f) << f << " Hz, 10 dB above it";
    EXPECT_TRUE(band.holds(model_m)) << threshold_kind(f) << f << " Hz: " << model_m * 1e6 << " um";
  }
}

// The shape alone, re 250 Hz, against the published slope (12 dB/octave from 40 Hz down to the
// minimum, 10-14 read). Calibration: the model's slope below 250 Hz (13 dB/octave, the least whole
// slope that also meets the published floor of 5 um or more at 40 Hz) was set on this row.
TEST(DiscriminationConformance, ThresholdShapeAgainstThePublishedSlope) {
  for (const double f : {40.0, 50.0, 80.0, 100.0, 150.0, 200.0}) {
    const Range slope = test::published_range("detection_threshold_slope_db_per_octave", f);
    const double octaves = std::log2(250.0 / f);
    const double model_db = 20.0 * std::log10(threshold_peak_displacement_m(f) / threshold_peak_displacement_m(250.0));
    std::printf("conformance,threshold_re_250hz_db,%g,,%.2f,%.2f,%.2f\n", f, model_db, slope.low * octaves, slope.high * octaves);
    EXPECT_TRUE(model_db >= slope.low * octaves && model_db <= slope.high * octaves)
        << kCalibration << f << " Hz: model +" << model_db << " dB re 250 Hz, published +" << slope.low * octaves << " to +"
        << slope.high * octaves;
  }
  // Above the minimum no published figure is in the data file: the model's +24 dB at 500 Hz is
  // ST-SIM's curve's rise, documented, not checked against people.
  EXPECT_NEAR(20.0 * std::log10(threshold_peak_displacement_m(500.0) / threshold_peak_displacement_m(250.0)), 23.7, 0.5);
}

TEST(DiscriminationConformance, PhaseIsNotFelt) {
  for (double f : kFrequenciesHz) {
    Tone shifted{f, 30.0};
    shifted.phase_rad = 2.0;
    EXPECT_GE(confusion(Tone{f, 30.0}, shifted), 0.45) << kOutOfSample << f;
  }
}

}  // namespace
}  // namespace vimg
