// Why the simulated participants of tests/study_fit/simulated (SimulatedParticipants.
// OnePairConfused40PercentOfTheTimeIsPredictedWithin0Point15) get a model that predicts their 40 %
// pair at about 0.27: neither a bias of the fit nor its lapse rate, but what the identification
// model can say about those trials. The images are that test's four textures as `vimg compare`
// renders them (a; b 4 dB weaker; c at a third of a's frequency; d 17 dB weaker), the trials theirs
// pooled over its three participants: a and b taken for each other 36 of 90 times each, c and d
// never confused.
//
// b and d differ from a along the same cues (level, and the envelope with it): b by 2 JNDs, d by
// 8.4. The closer a and b come, the closer d comes too, so a -> b can rise only so far before d
// takes the choices: no constants reach 0.40, and near the most they reach d is confused one time
// in seven, where the participants never confused it in 90 trials. The likelihood settles where
// d stays apart.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "primitives/perception/identification_choice.hpp"
#include "study/compare.hpp"
#include "study/fit_nelder_mead.hpp"
#include "study/fit_search.hpp"
#include "tests/study_fit/fit_files.hpp"

namespace vimg::study {
namespace {

constexpr double kCanvasMm = 40.0;

class FitMisspecified : public fit_test::FitFolderTest {
 protected:
  std::vector<CueMatrix> rendered_set() const {
    CompareRequest request;
    for (const fit_test::Surface& s : {fit_test::Surface{"a", 2.0, 0.7}, fit_test::Surface{"b", 2.0, 0.44},
                                       fit_test::Surface{"c", 6.0, 0.7}, fit_test::Surface{"d", 2.0, 0.1}}) {
      fit_test::write_surface_image(dir_, s, kCanvasMm);
      request.inputs.push_back(dir_ / (s.stem + ".vimg"));
    }
    const CompareResult r = run_compare(request);
    EXPECT_TRUE(r.ok());
    return {r.cues};
  }
};

// The participants' trials, pooled: [presented][chosen].
ChoiceCounts their_trials() {
  return {{54, 36, 0, 0}, {36, 54, 0, 0}, {0, 0, 90, 0}, {0, 0, 0, 90}};
}

const std::vector<std::size_t> kAll{0, 1, 2, 3};  // the lapse rate and the three weights

PerceptionMatrix predicted(const std::vector<CueMatrix>& cues, const DiscriminationConstants& k) {
  return identification_confusion(cues[0], k);
}

// The constants under which a -> b is predicted most often.
Optimum most_a_to_b(const FitProblem& p, const std::vector<double>& start) {
  const auto objective = [&](std::span<const double> theta) { return -predicted(*p.cues, constants_at(p.defaults, kAll, theta))[0][1]; };
  std::vector<double> lower, upper;
  for (const std::size_t m : kAll) {
    lower.push_back(theta_lower(m));
    upper.push_back(theta_upper(m));
  }
  NelderMeadOptions options;
  options.tolerance = 1e-12;
  const NelderMeadResult r = minimise_nelder_mead(objective, start, lower, upper, options);
  return {r.x, p.nll(kAll, r.x)};
}

TEST_F(FitMisspecified, APairConfused40PercentBesideOnesNeverConfusedOnTheSameCuesIsFittedNearerToAQuarter) {
  const std::vector<CueMatrix> cues = rendered_set();
  const FitProblem p{&cues, {their_trials()}, {}};

  // The maximum of the likelihood: a -> b about 0.27 with d kept apart, and no lapse.
  const Optimum best = fit_constants(p, kAll, default_start(kAll, {}));
  const DiscriminationConstants fitted = constants_at({}, kAll, best.theta);
  const PerceptionMatrix at_best = predicted(cues, fitted);
  EXPECT_GT(at_best[0][1], 0.22);
  EXPECT_LT(at_best[0][1], 0.32);
  EXPECT_GT(at_best[3][3], 0.95);
  EXPECT_LT(fitted.lapse_rate, 0.01) << "the lapse rate is not what holds the pair down";

  // No constants predict 0.40: the most the model can give a -> b is 0.33, and there d is
  // identified 86 % of the time, against the 90 of 90 the participants gave (ln L lower by over 20;
  // measured 27.4).
  const Optimum most = most_a_to_b(p, best.theta);
  const PerceptionMatrix at_most = predicted(cues, constants_at({}, kAll, most.theta));
  EXPECT_LT(at_most[0][1], 0.40);
  EXPECT_GT(at_most[0][1], at_best[0][1]);
  EXPECT_LT(at_most[3][3], 0.9);
  EXPECT_GT(most.nll - best.nll, 20.0);

  // Not a bias of the fit: trials the model can produce (the rows at those constants, 90
  // presentations each) are fitted back to the same prediction.
  ChoiceCounts expected(4, std::vector<double>(4, 0.0));
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) expected[i][j] = 90.0 * at_most[i][j];
  const FitProblem own{&cues, {expected}, {}};
  const Optimum recovered = fit_constants(own, kAll, default_start(kAll, {}));
  EXPECT_NEAR(predicted(cues, constants_at({}, kAll, recovered.theta))[0][1], at_most[0][1], 0.01);
  std::printf("a -> b: fitted %.3f (d correct %.3f, lapse %.4f); at most %.3f (d correct %.3f, ln L lower by %.1f)\n",
              at_best[0][1], at_best[3][3], fitted.lapse_rate, at_most[0][1], at_most[3][3], most.nll - best.nll);
}

}  // namespace
}  // namespace vimg::study
