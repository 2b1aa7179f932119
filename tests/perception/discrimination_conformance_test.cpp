// The discrimination model (primitives/perception/discrimination_cues.hpp + the choice rule with its
// default constants) against published vibrotactile psychophysics
// (tests/data/psychophysics/published_figures.csv, README.md there): it renders the classic
// stimuli, two at a time, and predicts how often a two-alternative trial confuses them.
//   - the model's JND (the difference confused in 25 % of two-alternative trials) falls within the
//     published range for frequency (Weber fraction), amplitude (dB) and gap detection (ms);
//   - a pair as far apart as the middle of the published range is confused 18-40 % of the time;
//   - well below a JND (5 % of frequency, 0.5 dB, a 2 ms gap) near chance (>= 0.4);
//   - several JNDs apart (an octave, 10 dB, a 30 ms gap) rarely (<= 0.05);
//   - the threshold: a sine below it is confused with silence half the time, one 10 dB above it
//     rarely, and the threshold itself is the published displacement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "primitives/perception/discrimination_choice.hpp"
#include "tests/perception/fixture_signals.hpp"
#include "tests/perception/tone_signals.hpp"

namespace vimg {
namespace {

using test::render_tone;
using test::strong_actuator;
using test::Tone;

struct Range {
  double low = 0.0;
  double high = 0.0;
  double middle() const { return std::sqrt(low * high); }
};

// The union of the published ranges of `quantity` whose frequency range holds frequency_hz.
Range published(const std::string& quantity, double frequency_hz) {
  Range r{1e300, -1e300};
  for (const auto& row : test::read_csv_rows(std::string(VIMG_TEST_DATA_DIR) + "/psychophysics/published_figures.csv")) {
    if (row.at("quantity") != quantity) continue;
    if (frequency_hz < std::stod(row.at("frequency_low_hz")) || frequency_hz > std::stod(row.at("frequency_high_hz"))) continue;
    r.low = std::min(r.low, std::stod(row.at("low")));
    r.high = std::max(r.high, std::stod(row.at("high")));
  }
  EXPECT_LT(r.low, r.high) << quantity << " at " << frequency_hz << " Hz";
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
  const Range r = published(quantity, f);
  const double model = jnd(p, 0.0, x.search_high);
  report(quantity, f, sl, model, r);
  EXPECT_GE(model, r.low) << quantity << ", " << f << " Hz at " << sl << " dB SL";
  EXPECT_LE(model, r.high) << quantity << ", " << f << " Hz at " << sl << " dB SL";
  const double at_middle = p(r.middle());
  EXPECT_GE(at_middle, 0.18) << quantity << ", " << f << " Hz";
  EXPECT_LE(at_middle, 0.40) << quantity << ", " << f << " Hz";
  EXPECT_GE(p(x.below), 0.40) << quantity << ", " << f << " Hz, " << x.below << " apart";
  EXPECT_LE(p(x.far), 0.05) << quantity << ", " << f << " Hz, " << x.far << " apart";
}

void expect_published_frequency_jnd(double sl) {
  for (double f : kFrequenciesHz) {
    const DiscriminationFeatures reference = features(Tone{f, sl});
    const auto p = [&](double fraction) { return confusion(reference, Tone{f * (1.0 + fraction), sl}); };
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
TEST(DiscriminationConformance, FrequencyWeberFractionIsThePublishedOneAt30DbSl) { expect_published_frequency_jnd(30.0); }
TEST(DiscriminationConformance, AmplitudeJndIsThePublishedOneAt20DbSl) { expect_published_amplitude_jnd(20.0); }
TEST(DiscriminationConformance, AmplitudeJndIsThePublishedOneAt30DbSl) { expect_published_amplitude_jnd(30.0); }

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

TEST(DiscriminationConformance, ThresholdIsThePublishedDisplacement) {
  const Range pacinian_um = published("detection_threshold_peak_displacement_um", 250.0);
  const Range floor_um = published("detection_threshold_peak_displacement_um", 25.0);
  for (double f : {10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0, 125.0, 150.0, 200.0, 250.0, 300.0, 400.0, 500.0}) {
    std::printf("conformance,threshold_peak_displacement_um,%g,,%.4g,,\n", f, skin_threshold_peak_displacement_m(f) * 1e6);
  }
  EXPECT_GE(skin_threshold_peak_displacement_m(250.0) * 1e6, pacinian_um.low);
  EXPECT_LE(skin_threshold_peak_displacement_m(250.0) * 1e6, pacinian_um.high);
  for (double f : {10.0, 20.0, 25.0, 40.0}) {
    EXPECT_GE(skin_threshold_peak_displacement_m(f) * 1e6, floor_um.low) << f;
    EXPECT_LE(skin_threshold_peak_displacement_m(f) * 1e6, floor_um.high) << f;
  }
  // The signal is acceleration: a sine whose acceleration is the published displacement times
  // (2 pi f)^2, 20 dB above the published threshold, reads 20 dB within the published range.
  for (double f : {25.0, 250.0}) {
    const Range r = f < 100.0 ? floor_um : pacinian_um;
    const double omega = 2.0 * std::numbers::pi * f;
    std::vector<double> x(8000);
    const LevelCalibration c = strong_actuator();
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = 10.0 * r.middle() * 1e-6 * omega * omega / c.full_scale_peak_acceleration_mps2 *
             std::sin(omega * static_cast<double>(i) / 8000.0);
    }
    const double level = analyse_discrimination(x, c).level_db;
    EXPECT_GE(level, 20.0 - 20.0 * std::log10(r.high / r.middle()) - 1.0) << f;
    EXPECT_LE(level, 20.0 + 20.0 * std::log10(r.middle() / r.low) + 1.0) << f;
  }
}

TEST(DiscriminationConformance, BelowThresholdIsSilenceAboveItIsNot) {
  const std::vector<double> silence(8000, 0.0);
  for (double f : kFrequenciesHz) {
    const auto against_silence = [&](double sl) {
      const DiscriminationFeatures tone = analyse_discrimination(render_tone(Tone{f, sl}), strong_actuator());
      const DiscriminationFeatures none = analyse_discrimination(silence, strong_actuator());
      return two_alternative_confusion(combined_distance_jnd(cue_distances(tone, none)));
    };
    EXPECT_GE(against_silence(-3.0), 0.45) << f << " Hz, 3 dB below threshold";
    EXPECT_LE(against_silence(10.0), 0.05) << f << " Hz, 10 dB above threshold";
  }
}

TEST(DiscriminationConformance, PhaseIsNotFelt) {
  for (double f : kFrequenciesHz) {
    Tone shifted{f, 30.0};
    shifted.phase_rad = 2.0;
    EXPECT_GE(confusion(Tone{f, 30.0}, shifted), 0.45) << f;
  }
}

}  // namespace
}  // namespace vimg
