// The fit of `vimg study fit` on simulated participants (study/fit_model.hpp): the likelihood is the
// model's equation, the fit recovers known constants within its 95 % profile intervals, the
// interval ends lie where the profile has fallen 1.92, constants the trials cannot identify keep
// their defaults with a warning, and too little data is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "study/fit_model.hpp"
#include "study/fit_nelder_mead.hpp"
#include "tests/study_fit/fit_simulation.hpp"

namespace vimg::study {
namespace {

using fit_test::SplitMix;

// |x_i - x_j| per cue of points in cue space (JND units).
CueMatrix cues_of(const std::vector<CueDistances>& points) {
  CueMatrix m(points.size(), std::vector<CueDistances>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < points.size(); ++j) {
      for (std::size_t c = 0; c < kCueCount; ++c) m[i][j][c] = std::abs(points[i][c] - points[j][c]);
    }
  }
  return m;
}

// Two sets of four images in the level-pitch-envelope space (identified 60-90 % of the time by the
// known truth: confused enough to inform the weights, distinct enough to inform the lapse rate).
FitData two_sets() {
  FitData d;
  d.set_names = {"near", "far"};
  d.set_cues = {cues_of({{0, 0, 0}, {1.5, 0, 0}, {0, 1.8, 0}, {0.75, 0.75, 1.5}}),
                cues_of({{0, 0, 0}, {3, 0.75, 0}, {0.45, 3, 0.75}, {1.5, 1.5, 3}})};
  return d;
}

// `participants` participants, each presented every image of every set `repetitions` times and
// choosing by `truth`.
void simulate(FitData& d, const DiscriminationConstants& truth, std::size_t participants, int repetitions, std::uint64_t seed) {
  SplitMix random(seed);
  for (std::size_t p = 0; p < participants; ++p) {
    d.participants.push_back("P" + std::to_string(p + 1));
    std::vector<ChoiceCounts> sets;
    for (const CueMatrix& cues : d.set_cues) {
      ChoiceCounts counts(cues.size(), std::vector<double>(cues.size(), 0.0));
      for (std::size_t i = 0; i < cues.size(); ++i) {
        const std::vector<double> row = fit_test::choice_row(cues, i, truth);
        for (int r = 0; r < repetitions; ++r) counts[i][fit_test::draw(row, random)] += 1.0;
      }
      sets.push_back(counts);
    }
    d.counts.push_back(sets);
  }
}

DiscriminationConstants known_truth() {
  DiscriminationConstants t;
  t.lapse_rate = 0.08;
  t.cue_weight = {2.0, 0.5, 1.4};
  return t;
}

const ConstantFit& constant(const ModelFit& fit, const std::string& name) {
  for (const ConstantFit& c : fit.report) {
    if (c.name == name) return c;
  }
  ADD_FAILURE() << "no constant " << name;
  return fit.report.front();
}

TEST(NelderMead, FindsRosenbrocksMinimum) {
  const auto rosenbrock = [](std::span<const double> x) {
    return 100.0 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1.0 - x[0], 2);
  };
  NelderMeadOptions options;
  options.tolerance = 1e-14;
  const NelderMeadResult r = minimise_nelder_mead(rosenbrock, {-1.2, 1.0}, {-5, -5}, {5, 5}, options);
  EXPECT_NEAR(r.x[0], 1.0, 1e-3);
  EXPECT_NEAR(r.x[1], 1.0, 1e-3);
  EXPECT_LT(r.value, 1e-6);
}

TEST(NelderMead, StaysInItsBoxAndEndsAtTheEdgeNearestAMinimumOutsideIt) {
  const auto bowl = [](std::span<const double> x) { return std::pow(x[0] - 5.0, 2) + std::pow(x[1] + 1.0, 2); };
  const NelderMeadResult r = minimise_nelder_mead(bowl, {0.5, 0.5}, {0, 0}, {2, 2});
  EXPECT_NEAR(r.x[0], 2.0, 1e-4);
  EXPECT_NEAR(r.x[1], 0.0, 1e-4);
  const NelderMeadResult none = minimise_nelder_mead([](std::span<const double>) { return 3.0; }, {}, {}, {});
  EXPECT_EQ(none.value, 3.0);
  EXPECT_EQ(none.evaluations, 1);
}

TEST(FitLikelihood, IsTheSumOfEachTrialsLnChoiceProbability) {
  FitData d = two_sets();
  simulate(d, known_truth(), 2, 3, 7);
  DiscriminationConstants k = known_truth();
  k.lapse_rate = 0.03;
  double expected = 0.0;
  const std::vector<ChoiceCounts> pooled = pooled_counts(d);
  for (std::size_t s = 0; s < d.set_cues.size(); ++s) {
    for (std::size_t i = 0; i < 4; ++i) {
      const std::vector<double> row = fit_test::choice_row(d.set_cues[s], i, k);
      for (std::size_t j = 0; j < 4; ++j) expected += pooled[s][i][j] * std::log(row[j]);
    }
  }
  EXPECT_NEAR(log_likelihood(d.set_cues, pooled, k), expected, 1e-9 * std::abs(expected));
  EXPECT_EQ(total_trials(pooled), 2.0 * 2 * 4 * 3);
  EXPECT_NEAR(chance_log_likelihood(pooled), -48.0 * std::log(4.0), 1e-9);
}

TEST(FitModel, RecoversKnownConstantsWithinTheirIntervalsAndBeatsTheDefaultsHeldOut) {
  FitData d = two_sets();
  const DiscriminationConstants truth = known_truth();
  simulate(d, truth, 6, 30, 2026);
  ASSERT_FALSE(fit_refusal(d));
  const ModelFit fit = fit_discrimination_model(d, {});
  EXPECT_TRUE(fit.warnings.empty()) << fit.warnings.front();
  for (std::size_t k = 0; k < kFitConstantCount; ++k) {
    const ConstantFit& c = constant(fit, fit_constant_name(k));
    ASSERT_TRUE(c.fitted) << c.name;
    const double true_value = constant_value(truth, k);
    EXPECT_LE(c.lower, true_value) << c.name << " fitted " << c.value;
    EXPECT_GE(c.upper, true_value) << c.name << " fitted " << c.value;
    EXPECT_LE(c.lower, c.value) << c.name;
    EXPECT_GE(c.upper, c.value) << c.name;
    // Informative: narrower than a factor of 3 either way.
    EXPECT_LT(c.upper, 3.0 * true_value) << c.name;
  }
  EXPECT_FALSE(constant(fit, "temperature_jnd").fitted);
  EXPECT_EQ(fit.constants.temperature_jnd, DiscriminationConstants{}.temperature_jnd);
  // Held out: each participant is predicted better by the others' fit than by the defaults, and
  // the total is the sum of the parts.
  ASSERT_EQ(fit.held_out.size(), 6u);
  double sum_fitted = 0.0, sum_trials = 0.0;
  for (const HeldOutParticipant& h : fit.held_out) {
    EXPECT_GT(h.ll_fitted, h.ll_default) << h.participant;
    EXPECT_GT(h.ll_fitted, h.ll_chance) << h.participant;
    sum_fitted += h.ll_fitted;
    sum_trials += h.trials;
  }
  EXPECT_NEAR(fit.held_out_ll_fitted, sum_fitted, 1e-9 * std::abs(sum_fitted));
  EXPECT_EQ(sum_trials, fit.trials);
  EXPECT_GE(fit.ll_fitted, fit.ll_default);
  EXPECT_GE(fit.ll_fitted, log_likelihood(d.set_cues, pooled_counts(d), truth) - 1e-6);  // the maximum
}

TEST(FitModel, TheProfileHasFallenAtLeast1Point92AtEachFiniteIntervalEnd) {
  FitData d = two_sets();
  simulate(d, known_truth(), 3, 20, 99);
  const ModelFit fit = fit_discrimination_model(d, {});
  const std::vector<ChoiceCounts> pooled = pooled_counts(d);
  for (std::size_t k = 0; k < kFitConstantCount; ++k) {
    const ConstantFit& c = constant(fit, fit_constant_name(k));
    if (!c.fitted) continue;
    // The profile at an end maximises over the others; the others held at the optimum give no more.
    for (const double end : {c.lower, c.upper}) {
      if (end == 0.0) continue;  // at the box's lower edge
      DiscriminationConstants at = fit.constants;
      set_constant_value(at, k, end);
      EXPECT_LE(log_likelihood(d.set_cues, pooled, at), fit.ll_fitted - kProfileDrop95 + 1e-3) << c.name << " at " << end;
    }
    // Halfway to an end the others can still make up most of the difference: the profile is not below the drop.
    DiscriminationConstants inside = fit.constants;
    set_constant_value(inside, k, 0.5 * (c.value + c.upper));
    EXPECT_GT(log_likelihood(d.set_cues, pooled, inside), fit.ll_fitted - 4.0 * kProfileDrop95) << c.name;
  }
}

TEST(FitModel, ACueThatNoPairDiffersInKeepsItsDefaultWithAWarning) {
  FitData d;
  d.set_names = {"flat"};
  d.set_cues = {cues_of({{0, 0, 0}, {1, 0, 0}, {0, 1.5, 0}, {2, 1, 0}})};  // no envelope anywhere
  simulate(d, known_truth(), 4, 25, 11);
  const ModelFit fit = fit_discrimination_model(d, {});
  const ConstantFit& envelope = constant(fit, "cue_weight.envelope");
  EXPECT_FALSE(envelope.fitted);
  EXPECT_EQ(fit.constants.cue_weight[2], DiscriminationConstants{}.cue_weight[2]);
  ASSERT_FALSE(fit.warnings.empty());
  EXPECT_NE(fit.warnings.front().find("cue_weight.envelope: no pair of images"), std::string::npos) << fit.warnings.front();
  EXPECT_TRUE(constant(fit, "cue_weight.level").fitted);
  EXPECT_TRUE(constant(fit, "cue_weight.pitch").fitted);
}

TEST(FitModel, AlwaysRightAnswersCannotBoundTheWeightsFromAboveSoTheyKeepTheirDefaults) {
  FitData d;
  d.set_names = {"distinct"};
  d.set_cues = {cues_of({{0, 0, 0}, {6, 0, 0}, {0, 6, 0}, {0, 0, 6}})};
  for (const char* p : {"P1", "P2", "P3"}) {
    d.participants.push_back(p);
    ChoiceCounts counts(4, std::vector<double>(4, 0.0));
    for (std::size_t i = 0; i < 4; ++i) counts[i][i] = 20;
    d.counts.push_back({counts});
  }
  const ModelFit fit = fit_discrimination_model(d, {});
  for (const char* name : {"cue_weight.level", "cue_weight.pitch", "cue_weight.envelope"}) {
    EXPECT_FALSE(constant(fit, name).fitted) << name;
    bool warned = false;
    for (const std::string& w : fit.warnings) warned = warned || (w.rfind(name, 0) == 0 && w.find("cannot identify") != std::string::npos);
    EXPECT_TRUE(warned) << name;
  }
  EXPECT_EQ(fit.constants.cue_weight, DiscriminationConstants{}.cue_weight);
  // The lapse rate is identified: no wrong answer in 240 says it is small.
  const ConstantFit& lapse = constant(fit, "lapse_rate");
  EXPECT_TRUE(lapse.fitted);
  EXPECT_TRUE(lapse.lower_at_edge);
  EXPECT_LT(lapse.upper, 0.05);
}

TEST(FitModel, RefusesNoTrialsOneParticipantAndTooFewTrials) {
  FitData none = two_sets();
  ASSERT_TRUE(fit_refusal(none));
  EXPECT_NE(fit_refusal(none)->find("no trials"), std::string::npos);
  FitData one = two_sets();
  simulate(one, known_truth(), 1, 10, 1);
  ASSERT_TRUE(fit_refusal(one));
  EXPECT_NE(fit_refusal(one)->find("one participant only (P1)"), std::string::npos) << *fit_refusal(one);
  FitData few = two_sets();
  simulate(few, known_truth(), 2, 2, 1);  // 32 trials for 4 free constants
  ASSERT_TRUE(fit_refusal(few));
  EXPECT_NE(fit_refusal(few)->find("32 trials for 4 free constants: at least 10 trials per constant (40)"), std::string::npos)
      << *fit_refusal(few);
  FitData enough = two_sets();
  simulate(enough, known_truth(), 2, 3, 1);  // 48
  EXPECT_FALSE(fit_refusal(enough));
}

}  // namespace
}  // namespace vimg::study
