// Perceptual similarity and predicted confusion: the behaviour issue 20 asks of `vimg compare`
// (docs/perception.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "primitives/actuator/actuator_model.hpp"
#include "primitives/perception/perceptual_similarity.hpp"
#include "primitives/perception/predicted_confusion.hpp"
#include "texture_signals.hpp"

namespace vimg {
namespace {

constexpr double kSeconds = 10.0;

std::vector<PerceptualFeatures> analyse_all(const std::vector<std::vector<double>>& signals) {
  std::vector<PerceptualFeatures> features;
  for (const auto& s : signals) features.push_back(analyse(s));
  return features;
}

PerceptionMatrix confusion_of(const std::vector<std::vector<double>>& signals) {
  return predicted_confusion(similarity_matrix(analyse_all(signals)));
}

void print(const char* title, const PerceptionMatrix& m) {
  std::printf("%s\n", title);
  for (const auto& row : m) {
    for (double v : row) std::printf(" %8.5f", v);
    std::printf("\n");
  }
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

TEST(PerceptualSimilarity, IdenticalSignalsAreOne) {
  const auto a = analyse(test::surface_signal(kSeconds));
  const auto s = perceptual_similarity(a, a);
  EXPECT_EQ(s.value, 1.0);
  EXPECT_EQ(s.level_difference_db, 0.0);
}

TEST(PerceptualSimilarity, IsSymmetricAndWithinZeroOne) {
  const auto features = analyse_all({test::dot_signal(kSeconds), test::line_signal(kSeconds), test::surface_signal(kSeconds),
                                     test::surface_signal(kSeconds, 0.3, 70.0)});
  for (const auto& a : features) {
    for (const auto& b : features) {
      const double ab = perceptual_similarity(a, b).value, ba = perceptual_similarity(b, a).value;
      EXPECT_DOUBLE_EQ(ab, ba);
      EXPECT_GE(ab, 0.0);
      EXPECT_LE(ab, 1.0);
    }
  }
}

TEST(PerceptualSimilarity, TwoSignalsBelowThresholdAreIndistinguishable) {
  // A texture and noise, both far below threshold at 1e-4 of full scale.
  std::vector<double> noise = test::silence(kSeconds);
  std::uint64_t state = 1;
  for (double& v : noise) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    v = 1e-4 * (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
  }
  const auto a = analyse(test::surface_signal(kSeconds, 1e-4));
  const auto b = analyse(noise);
  EXPECT_EQ(a.levels.max_felt_db(), 0.0);
  EXPECT_EQ(b.levels.max_felt_db(), 0.0);
  EXPECT_EQ(perceptual_similarity(a, b).value, 1.0);
}

TEST(PerceptualSimilarity, AStrongAndAFaintVersionOfOneTextureDiffer) {
  const auto strong = analyse(test::surface_signal(kSeconds, 0.8));
  const auto faint = analyse(test::surface_signal(kSeconds, 0.2));  // 12 dB lower, still felt
  EXPECT_GT(faint.levels.max_felt_db(), 6.0);
  const auto s = perceptual_similarity(strong, faint);
  EXPECT_GT(s.structure, 0.95);  // the same waveform: ST-SIM can hardly tell them apart
  EXPECT_NEAR(s.level_difference_db, 20.0 * std::log10(0.8 / 0.2), 1e-6);
  EXPECT_NEAR(s.level, std::exp2(-12.04 / 20.0), 1e-3);
  EXPECT_LT(s.value, 0.7);
  const auto p = predicted_confusion({{1.0, s.value}, {s.value, 1.0}});
  EXPECT_GT(p[0][0], 0.95);
  EXPECT_TRUE(likely_confused_pairs(p).empty());
}

TEST(PredictedConfusion, TwoIdenticalSignalsSplitEvenlyAndAreFlagged) {
  const auto surface = test::surface_signal(kSeconds);
  const PerceptionMatrix alone = confusion_of({surface, surface});
  EXPECT_DOUBLE_EQ(alone[0][0], 0.5);
  EXPECT_DOUBLE_EQ(alone[0][1], 0.5);
  EXPECT_DOUBLE_EQ(alone[1][0], 0.5);
  EXPECT_DOUBLE_EQ(alone[1][1], 0.5);
  const auto pairs = likely_confused_pairs(alone);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].a, 0u);
  EXPECT_EQ(pairs[0].b, 1u);
  EXPECT_DOUBLE_EQ(pairs[0].p, 0.5);

  // Within a set: each twin's row splits evenly between the twins, and only they are flagged.
  const PerceptionMatrix in_set = confusion_of({test::dot_signal(kSeconds), surface, test::line_signal(kSeconds), surface});
  print("dot, surface, line, surface", in_set);
  for (std::size_t row : {1u, 3u}) {
    EXPECT_DOUBLE_EQ(in_set[row][1], in_set[row][3]);
    EXPECT_GT(in_set[row][1], 0.45);
  }
  const auto flagged = likely_confused_pairs(in_set);
  ASSERT_EQ(flagged.size(), 1u);
  EXPECT_EQ(flagged[0].a, 1u);
  EXPECT_EQ(flagged[0].b, 3u);
}

TEST(PredictedConfusion, DotLineAndSurfaceArePredictedApart) {
  const PerceptionMatrix p = confusion_of({test::dot_signal(kSeconds), test::line_signal(kSeconds), test::surface_signal(kSeconds)});
  print("dot, line, surface", p);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GE(p[i][i], 0.9) << i;
  EXPECT_TRUE(likely_confused_pairs(p).empty());
}

TEST(PredictedConfusion, TexturesDifferingBelowTheLraBandAreMoreConfusableThroughIt) {
  // The same 175 Hz component; below the LRA's felt band one has 30 Hz, the other 45 Hz.
  const auto a = test::partials_signal(kSeconds, {{0.5, 175.0}, {0.5, 30.0}});
  const auto b = test::partials_signal(kSeconds, {{0.5, 175.0}, {0.5, 45.0}});
  const PerceptionMatrix ideal = confusion_of({a, b});
  const PerceptionMatrix lra = confusion_of({through_lra(a), through_lra(b)});
  print("ideal", ideal);
  print("lra", lra);
  EXPECT_GT(lra[0][1], ideal[0][1] + 0.2);
  EXPECT_GT(lra[1][0], ideal[1][0] + 0.2);
  EXPECT_TRUE(likely_confused_pairs(ideal).empty());
  EXPECT_FALSE(likely_confused_pairs(lra).empty());
}

}  // namespace
}  // namespace vimg
