// The discrimination model on synthetic primitives (tests/perception/texture_signals.hpp) and the
// actuator model: what a designer relies on, as properties and against the choice equation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "primitives/actuator/actuator_model.hpp"
#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/predicted_confusion.hpp"
#include "primitives/random/splitmix64.hpp"
#include "texture_signals.hpp"

namespace vimg {
namespace {

constexpr double kSeconds = 10.0;

PerceptionMatrix confusion_of(const std::vector<std::vector<double>>& signals) {
  std::vector<DiscriminationFeatures> features;
  for (const auto& s : signals) features.push_back(analyse_discrimination(s));
  return discrimination_confusion(cue_matrix(features));
}

// The modelled acceleration of an LRA (resonance 175 Hz, Q 10) driven by the signal.
std::vector<double> through_lra(const std::vector<double>& drive) {
  ResponseParams params;
  params.model = ResponseModel::lra;
  params.resonance_hz = 175.0;
  params.q = 10.0;
  ActuatorModel lra(params, test::kRateHz);
  std::vector<double> out(drive.size());
  for (std::size_t n = 0; n < drive.size(); ++n) out[n] = lra.process(drive[n]);
  return out;
}

// Seeded noise bursts of random level and length: signals with nothing in common by construction.
std::vector<double> random_signal(std::uint64_t seed) {
  SplitMix64 random(seed);
  const auto next = [&random] { return random.unit(); };
  std::vector<double> x(static_cast<std::size_t>((0.5 + 2.0 * next()) * test::kRateHz), 0.0);
  const double gain = std::pow(10.0, -2.0 * next());
  const double frequency_hz = 20.0 + 400.0 * next();
  for (std::size_t n = 0; n < x.size(); ++n) {
    if (next() < 0.001) continue;
    x[n] = gain * (0.7 * std::sin(2.0 * 3.141592653589793 * frequency_hz * static_cast<double>(n) / test::kRateHz) +
                   0.3 * (next() - 0.5));
  }
  return x;
}

TEST(DiscriminationModel, CueDistancesAreSymmetricNonNegativeAndZeroForIdenticalSignals) {
  std::vector<DiscriminationFeatures> f;
  for (std::uint64_t seed = 0; seed < 8; ++seed) f.push_back(analyse_discrimination(random_signal(seed)));
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (std::size_t j = 0; j < f.size(); ++j) {
      const CueDistances ij = cue_distances(f[i], f[j]);
      const CueDistances ji = cue_distances(f[j], f[i]);
      for (std::size_t c = 0; c < kCueCount; ++c) {
        EXPECT_GE(ij[c], 0.0) << cue_name(c);
        EXPECT_DOUBLE_EQ(ij[c], ji[c]) << cue_name(c);
        if (i == j) {
          EXPECT_EQ(ij[c], 0.0) << cue_name(c);
        }
      }
    }
  }
}

TEST(DiscriminationModel, TwoIdenticalSignalsSplitEvenlyAndAreFlagged) {
  const auto surface = test::surface_signal(kSeconds);
  const PerceptionMatrix alone = confusion_of({surface, surface});
  EXPECT_DOUBLE_EQ(alone[0][0], 0.5);
  EXPECT_DOUBLE_EQ(alone[0][1], 0.5);
  const auto pairs = likely_confused_pairs(alone);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_DOUBLE_EQ(pairs[0].p, 0.5);
  // Within a set: each twin's row splits evenly between the twins, and only they are flagged.
  const PerceptionMatrix in_set = confusion_of({test::dot_signal(kSeconds), surface, test::line_signal(kSeconds), surface});
  for (std::size_t row : {1u, 3u}) {
    EXPECT_DOUBLE_EQ(in_set[row][1], in_set[row][3]);
    EXPECT_GT(in_set[row][1], 0.45);
  }
  const auto flagged = likely_confused_pairs(in_set);
  ASSERT_EQ(flagged.size(), 1u);
  EXPECT_EQ(flagged[0].a, 1u);
  EXPECT_EQ(flagged[0].b, 3u);
}

TEST(DiscriminationModel, DotLineAndSurfaceArePredictedApart) {
  for (const bool lra : {false, true}) {
    std::vector<std::vector<double>> s = {test::dot_signal(kSeconds), test::line_signal(kSeconds), test::surface_signal(kSeconds)};
    if (lra) {
      for (auto& x : s) x = through_lra(x);
    }
    const PerceptionMatrix p = confusion_of(s);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_GE(p[i][i], 0.9) << i << (lra ? " through the LRA" : "");
    EXPECT_TRUE(likely_confused_pairs(p).empty());
  }
}

TEST(DiscriminationModel, TexturesDifferingBelowTheLraBandAreMoreConfusableThroughIt) {
  // The same 175 Hz component; below the LRA's felt band one has 30 Hz, the other 45 Hz (a Weber
  // fraction of 0.5: two JNDs of the lower partial). The model's pitch is one centroid, to which the
  // lower partial gives about a third of the excitation, so the ideal actuator moves it about half
  // a pitch JND (confused about a third of the time); through the LRA the two are alike.
  const auto a = test::partials_signal(kSeconds, {{0.5, 175.0}, {0.5, 30.0}});
  const auto b = test::partials_signal(kSeconds, {{0.5, 175.0}, {0.5, 45.0}});
  const PerceptionMatrix ideal = confusion_of({a, b});
  const PerceptionMatrix lra = confusion_of({through_lra(a), through_lra(b)});
  EXPECT_GE(lra[0][1], 0.45);
  EXPECT_GT(lra[0][1], ideal[0][1] + 0.1);
  EXPECT_GT(lra[1][0], ideal[1][0] + 0.1);
  EXPECT_FALSE(likely_confused_pairs(lra).empty());
}

std::vector<double> burst_at(double start_s) {
  std::vector<double> x = test::silence(2.0);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / test::kRateHz - start_s;
    if (t >= 0.0 && t < 0.030) x[n] = 0.8 * std::sin(2.0 * 3.141592653589793 * 175.0 * t);
  }
  return x;
}

// Free exploration does not repeat its timing: a shift within kTimingToleranceMs goes unnoticed,
// one of 200 ms (a feature in another place) does not.
TEST(DiscriminationModel, SmallTimingShiftsAreNotFeltLargeOnesAre) {
  EXPECT_GE(confusion_of({burst_at(0.5), burst_at(0.5 + 0.010)})[0][1], 0.45);
  EXPECT_LE(confusion_of({through_lra(burst_at(0.2)), through_lra(burst_at(0.4))})[0][1], 0.05);
}

}  // namespace
}  // namespace vimg
