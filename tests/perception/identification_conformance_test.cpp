// Identification of rendered stimuli against published identification figures
// (tests/data/psychophysics/published_figures.csv, README.md there): sets of tones and rhythms are
// synthesised at sensation levels above the published threshold (never the model's own), analysed
// (analyse_discrimination), compared (cue_matrix) and identified (identification_confusion), the
// path `vimg compare` takes; the information transfer of the predicted matrix is checked against a
// direct mutual-information sum written here. Every check says its kind (docs/perception.md):
//   [calibration]    kContextNoisePerDPrime was set on Rabinowitz et al.'s ranges (one-dimensional
//                    sets 1-2 bits, three-dimensional 4-5), here and in identification_choice_test,
//                    so those checks test the rendered path (threshold, summation, cues), not a
//                    prediction;
//   [out of sample]  nothing was set on Azadi & Jones's nine tactons, nor on the segregation of
//                    rhythms (Jurado et al. 2021).
// The stimuli's values are ours: the sources' abstracts give the dimensions, not the values, and
// their full texts were not found (docs/identification.md, "Identification of rendered sets").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "primitives/perception/identification_choice.hpp"
#include "primitives/perception/information_transfer.hpp"
#include "primitives/random/splitmix64.hpp"
#include "tests/perception/tone_signals.hpp"

namespace vimg {
namespace {

using test::render_pulses;
using test::strong_actuator;
using test::Tone;

constexpr const char* kCalibration = "[calibration] ";
constexpr const char* kOutOfSample = "[out of sample] ";

// One stimulus of a set: a tone at a sensation level above the published threshold, steady
// (pulses 1) or as a rhythm.
struct Stimulus {
  double frequency_hz = 250.0;
  double sensation_level_db = 30.0;
  int pulses = 1;
};

// The path of `vimg compare` after rendering: features, cue matrix, identification.
PerceptionMatrix identify(const std::vector<Stimulus>& set) {
  std::vector<DiscriminationFeatures> features;
  for (const Stimulus& s : set)
    features.push_back(analyse_discrimination(render_pulses(Tone{s.frequency_hz, s.sensation_level_db}, s.pulses), strong_actuator()));
  return identification_confusion(cue_matrix(features));
}

// Mutual information as its definition's double sum, every image presented alike:
// sum_ij p(i) p(j|i) log2(p(j|i) / q(j)), q(j) = sum_i p(i) p(j|i). Written apart from
// information_transfer_bits, against which it is checked.
double direct_mutual_information(const PerceptionMatrix& p) {
  const double presented = 1.0 / static_cast<double>(p.size());
  std::vector<double> chosen(p.size(), 0.0);
  for (const auto& row : p)
    for (std::size_t j = 0; j < row.size(); ++j) chosen[j] += presented * row[j];
  double bits = 0.0;
  for (const auto& row : p)
    for (std::size_t j = 0; j < row.size(); ++j)
      if (row[j] > 0.0) bits += presented * row[j] * std::log2(row[j] / chosen[j]);
  return bits;
}

double it_bits(const PerceptionMatrix& p) {
  const double it = information_transfer_bits(p);
  EXPECT_NEAR(it, direct_mutual_information(p), 1e-9);
  return it;
}

double percent_correct(const PerceptionMatrix& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) sum += p[i][i];
  return 100.0 * sum / static_cast<double>(p.size());
}

test::PublishedRange published(const std::string& quantity) {
  const test::PublishedRange r = test::published_range(quantity, NAN);
  EXPECT_LE(r.low, r.high) << quantity << ": no published row";
  return r;
}

// n values from low to high, evenly on a log scale (geometric) or a linear one.
std::vector<double> spread(double low, double high, std::size_t n, bool geometric) {
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n - 1);
    v.push_back(geometric ? low * std::pow(high / low, t) : low + (high - low) * t);
  }
  return v;
}

constexpr std::size_t kSetSizes[] = {3, 4, 6, 8, 12};

std::string fmt(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// One line per figure on the test's output, for scripts/plot_perception_conformance.py:
// identification,SET,MEMBERS,MODEL,PUBLISHED_LOW,PUBLISHED_HIGH
void report(const std::string& set, std::size_t members, double model, const test::PublishedRange& r) {
  std::printf("identification,%s,%zu,%.4f,%g,%g\n", set.c_str(), members, model, r.low, r.high);
}

// One dimension: n members over [low, high] of frequency (at 30 dB SL) or of sensation level (at
// frequency_hz); IT within the published one-dimensional range at every size, and from 6 to 12
// members within the published growth.
void expect_one_dimension(const char* what, double low, double high, bool frequency, double frequency_hz = 250.0) {
  const test::PublishedRange range = published("identification_information_transfer_bits_one_dimension");
  const test::PublishedRange growth = published("identification_information_gain_bits_6_to_12_members");
  double at_six = 0.0;
  for (const std::size_t n : kSetSizes) {
    std::vector<Stimulus> set;
    for (const double v : spread(low, high, n, frequency)) set.push_back(frequency ? Stimulus{v, 30.0} : Stimulus{frequency_hz, v});
    const double it = it_bits(identify(set));
    report(std::string(what) + " " + fmt(low) + "-" + fmt(high), n, it, range);
    EXPECT_TRUE(range.holds(it)) << kCalibration << what << " " << low << "-" << high << ", " << n << " members: " << it << " bits";
    if (n == 6) at_six = it;
    if (n == 12) {
      EXPECT_TRUE(growth.holds(it - at_six)) << kCalibration << what << ": " << it - at_six << " bits from 6 to 12 members";
    }
  }
}

// Rabinowitz, Houtsma, Durlach & Delhorne (1987): frequency at equal sensation level over 2.6 and
// 3.9 octaves; level over 30 and 40 dB at 250 Hz (Pacinian) and at 50 Hz.
TEST(IdentificationConformance, OneDimensionalSetsOfFrequencyTransferOneToTwoBits) {
  expect_one_dimension("frequency (Hz)", 40.0, 250.0, true);
  expect_one_dimension("frequency (Hz)", 20.0, 300.0, true);
}

TEST(IdentificationConformance, OneDimensionalSetsOfLevelTransferOneToTwoBits) {
  expect_one_dimension("level at 250 Hz (dB SL)", 15.0, 45.0, false, 250.0);
  expect_one_dimension("level at 250 Hz (dB SL)", 10.0, 50.0, false, 250.0);
  expect_one_dimension("level at 50 Hz (dB SL)", 10.0, 50.0, false, 50.0);
}

// Rabinowitz et al.'s three dimensions were intensity, frequency and contactor area; the model has
// no spatial cue, so the third dimension here is rhythm (1 to 5 bursts in 1 s). Five rhythms alone
// are identified without error (2.32 bits, log2 5; next test: each 12 JNDs or more from the
// others). Frequency and level together transfer less than their one-dimensional sets add to: a
// tone's frequency moves the level cue as well as the pitch cue (about 2 level JNDs per step of
// the 40-250 Hz set), so the level cue's range and its context noise grow, the interaction
// Rabinowitz et al. found largest for intensity. Calibration: G was set on this range.
TEST(IdentificationConformance, AThreeDimensionalSetTransfersFourToFiveBits) {
  const std::vector<double> frequencies = spread(40.0, 250.0, 5, true);
  const std::vector<double> levels = spread(10.0, 50.0, 5, false);
  std::vector<Stimulus> set, rhythms, frequency_by_level, frequency_alone, level_alone;
  for (const double f : frequencies) {
    frequency_alone.push_back({f, 30.0, 1});
    for (const double sl : levels) {
      frequency_by_level.push_back({f, sl, 1});
      for (const int pulses : {1, 2, 3, 4, 5}) set.push_back({f, sl, pulses});
    }
  }
  for (const double sl : levels) level_alone.push_back({250.0, sl, 1});
  for (const int pulses : {1, 2, 3, 4, 5}) rhythms.push_back({250.0, 30.0, pulses});
  const double it = it_bits(identify(set));
  const double rhythm_it = it_bits(identify(rhythms));
  const double two_it = it_bits(identify(frequency_by_level));
  const double frequency_it = it_bits(identify(frequency_alone));
  const double level_it = it_bits(identify(level_alone));
  const test::PublishedRange range = published("identification_information_transfer_bits_three_dimensions");
  report("3 dimensions: bits", set.size(), it, range);
  std::printf("three dimensions: rhythm alone %.2f bits, frequency x level %.2f bits (frequency alone %.2f, level alone %.2f)\n",
              rhythm_it, two_it, frequency_it, level_it);
  EXPECT_TRUE(range.holds(it)) << kCalibration << it << " bits, published " << range.low << "-" << range.high;
  EXPECT_GT(rhythm_it, std::log2(5.0) - 0.05) << "five rhythms alone: " << rhythm_it << " bits";
  EXPECT_LT(two_it, frequency_it + level_it) << "frequency x level: " << two_it << " bits, no interaction";
  EXPECT_GT(two_it, std::max(frequency_it, level_it)) << "frequency x level: " << two_it << " bits, the cues do not add";
}

// Successive vibrotactile stimuli separated by at least about 80-90 ms are felt apart (Jurado et al.
// 2021, the critical segregation rate of about 11-12 Hz), so rhythms whose silences are longer are
// plainly different rhythms: 2 to 5 bursts in 1 s (silences of 333 to 111 ms) against the steady tone
// and one another, confused in at most 5 % of two-interval trials. Out of sample: nothing was set on
// it (the rhythm track's context is half the slow envelope's window, kRhythmContextMs).
TEST(IdentificationConformance, RhythmsSlowerThanThePublishedSegregationRateAreToldApart) {
  const test::PublishedRange segregation = published("temporal_segregation_interval_ms");
  std::vector<DiscriminationFeatures> f;
  for (const int pulses : {1, 2, 3, 4, 5}) {
    if (pulses > 1) {
      EXPECT_GT(1000.0 / (2 * pulses - 1), segregation.high) << pulses << " bursts: silences within the published limit";
    }
    f.push_back(analyse_discrimination(render_pulses(Tone{250.0, 30.0}, pulses), strong_actuator()));
  }
  const CueMatrix d = cue_matrix(f);
  std::printf("rhythm: envelope JNDs from the steady tone: 2 bursts %.1f, 3 bursts %.1f, 4 bursts %.1f, 5 bursts %.1f\n", d[0][1][2],
              d[0][2][2], d[0][3][2], d[0][4][2]);
  for (std::size_t i = 0; i < f.size(); ++i)
    for (std::size_t j = i + 1; j < f.size(); ++j) {
      const double p = two_alternative_confusion(combined_distance_jnd(d[i][j]));
      EXPECT_LE(p, 0.05) << kOutOfSample << i + 1 << " against " << j + 1 << " bursts: confused " << p;
    }
}

// Azadi & Jones (2014): nine tactons over frequency, amplitude and temporal profile, each
// presented 8 times. Ours: an orthogonal array (each value of each dimension in three tactons, two
// tactons share at most one value): 40, 100, 250 Hz; 15, 25, 35 dB SL; 1, 2, 4 bursts in 1 s.
std::vector<Stimulus> nine_tactons() {
  const double f[] = {40.0, 100.0, 250.0};
  const double sl[] = {15.0, 25.0, 35.0};
  const int pulses[] = {1, 2, 4};
  std::vector<Stimulus> set;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) set.push_back({f[a], sl[b], pulses[(a + b) % 3]});
  return set;
}

// The IT a participant's 72 trials estimate (8 per tacton drawn from the predicted rows), averaged
// over 2000 seeded participants: the estimate is biased upwards on so few trials (Miller-Madow:
// about (9 - 1)^2 / (2 * 72 ln 2) = 0.64 bits), and the published 2.41 bits is such an estimate.
double sampled_it_bits(const PerceptionMatrix& p, int presentations) {
  SplitMix64 random(20140101);
  constexpr int kParticipants = 2000;
  double sum = 0.0;
  for (int participant = 0; participant < kParticipants; ++participant) {
    PerceptionMatrix counts(p.size(), std::vector<double>(p.size(), 0.0));
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (int t = 0; t < presentations; ++t) {
        double u = random.unit();
        std::size_t j = 0;
        while (j + 1 < p.size() && u >= p[i][j]) u -= p[i][j++];
        counts[i][j] += 1.0;
      }
    }
    sum += information_transfer_bits(counts);
  }
  return sum / kParticipants;
}

// The model identifies our nine tactons better than Azadi & Jones's participants identified
// theirs: pinned as a deviation (docs/identification.md). Their values are not in the abstract (nor in
// any text found); ours are 4 frequency JNDs and 5 level JNDs apart with three rhythms each 12 JNDs
// or more apart, where the model sees little context noise (few values per cue) and multiplies the
// cues' confusabilities (every two tactons differ on two cues or three).
TEST(IdentificationConformance, NineTactonsOverThreeDimensionsAreIdentifiedBetterThanPublished) {
  const PerceptionMatrix p = identify(nine_tactons());
  const double correct = percent_correct(p);
  const double it = it_bits(p);
  const double sampled = sampled_it_bits(p, 8);
  const test::PublishedRange pc = published("identification_percent_correct_nine_tactons");
  const test::PublishedRange bits = published("identification_information_transfer_bits_nine_tactons");
  std::printf("nine tactons: %.3f bits of the matrix\n", it);
  report("9 tactons: % correct", 9, correct, pc);
  report("9 tactons: bits from 72 trials", 9, sampled, bits);
  EXPECT_GT(correct, pc.high) << kOutOfSample << "(pinned deviation) " << correct << " % correct: now within " << pc.low << "-"
                              << pc.high << ", redo docs/identification.md";
  EXPECT_GT(sampled, bits.high) << kOutOfSample << "(pinned deviation) " << sampled << " bits estimated from 72 trials";
  EXPECT_LT(correct, 99.9) << kOutOfSample << "(pinned deviation) " << correct << " % correct";
}

}  // namespace
}  // namespace vimg
