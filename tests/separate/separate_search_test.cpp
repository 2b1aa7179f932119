// The search of `vimg separate` (study/separate_search.hpp) on analytic spaces, against exhaustive
// search over the same steps: it reaches the target when any state does, its total change is
// within 10 % of the least, and it obeys --keep and --vary exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "tests/separate/analytic_space.hpp"

namespace vimg {
namespace {

using study::SeparationSetting;
using study::TactileParameter;

constexpr std::size_t kPeriod = static_cast<std::size_t>(TactileParameter::period);
constexpr std::size_t kGain = static_cast<std::size_t>(TactileParameter::gain);
constexpr std::size_t kPattern = static_cast<std::size_t>(TactileParameter::pattern);

study::TactileParameterSet only(std::initializer_list<TactileParameter> ps) {
  study::TactileParameterSet s{};
  for (const TactileParameter p : ps) s[static_cast<std::size_t>(p)] = true;
  return s;
}

// Every setting over the given parameters' steps (the others at 0), as exhaustive search takes them.
std::vector<SeparationSetting> all_settings(const study::TactileParameterSet& vary, study::SeparationSpace& space,
                                            std::size_t image) {
  std::vector<SeparationSetting> out{SeparationSetting{}};
  for (std::size_t p = 0; p < study::kTactileParameterCount; ++p) {
    if (!vary[p]) continue;
    const study::StepRange r = study::step_range(static_cast<TactileParameter>(p));
    std::vector<SeparationSetting> next;
    for (const SeparationSetting& s : out) {
      for (int v = r.lowest; v <= r.highest; ++v) {
        SeparationSetting t = s;
        t[p] = static_cast<std::int8_t>(v);
        next.push_back(t);
      }
    }
    out = std::move(next);
  }
  std::vector<SeparationSetting> allowed;
  for (const SeparationSetting& s : out)
    if (space.allowed(image, s)) allowed.push_back(s);
  return allowed;
}

// Images close together in pitch (a confused set), at random, seeded.
std::vector<test::AnalyticImage> confused_set(std::mt19937& rng, std::size_t n) {
  std::uniform_real_distribution<double> near(0.0, 1.2);
  std::vector<test::AnalyticImage> images;
  for (std::size_t i = 0; i < n; ++i) images.push_back({{20.0, 10.0 + near(rng), 0.0}});
  return images;
}

// Returns greedy / exhaustive total change.
double expect_near_exhaustive(std::size_t images, const study::TactileParameterSet& vary, unsigned seed,
                              int period_limit) {
  std::mt19937 rng(seed);
  test::AnalyticSpace space(confused_set(rng, images));
  space.period_limit = period_limit;
  study::SeparationRequest q;
  q.target = 0.9;
  q.vary = vary;
  const study::SeparationOutcome greedy = study::run_separation_search(space, q);
  std::vector<std::vector<SeparationSetting>> choices;
  for (std::size_t i = 0; i < images; ++i) choices.push_back(all_settings(vary, space, i));
  const study::SeparationOutcome best = study::exhaustive_separation(space, q, choices);
  EXPECT_TRUE(best.reached) << "seed " << seed << ": the case should be reachable";
  if (!best.reached) return 0.0;
  EXPECT_TRUE(greedy.reached) << "seed " << seed;
  EXPECT_LE(greedy.total_change_jnd, 1.10 * best.total_change_jnd + 1e-9)
      << "seed " << seed << ": greedy " << greedy.total_change_jnd << " JNDs, exhaustive " << best.total_change_jnd;
  for (const double p : greedy.identified) EXPECT_GE(p, q.target - 1e-12);
  return best.total_change_jnd > 0.0 ? greedy.total_change_jnd / best.total_change_jnd : 1.0;
}

// The worst ratio over the seeds, printed for docs/separate.md.
void over_seeds(const char* what, std::size_t images, const study::TactileParameterSet& vary, unsigned first,
                unsigned last, int period_limit = 6) {
  double worst = 0.0;
  for (unsigned seed = first; seed <= last; ++seed)
    worst = std::max(worst, expect_near_exhaustive(images, vary, seed, period_limit));
  std::printf("%s: worst greedy / exhaustive over %u seeds: %.3f\n", what, last - first + 1, worst);
}

TEST(SeparationSearch, ThreeImagesPeriodAndPatternWithinTenPercentOfExhaustive) {
  over_seeds("3 images, period and pattern", 3, only({TactileParameter::period, TactileParameter::pattern}), 1, 12);
}

TEST(SeparationSearch, TwoImagesAllThreeCuesWithinTenPercentOfExhaustive) {
  over_seeds("2 images, period, pattern and gain", 2,
             only({TactileParameter::period, TactileParameter::pattern, TactileParameter::gain}), 11, 18);
}

TEST(SeparationSearch, ThreeImagesOnePeriodWithinTenPercentOfExhaustive) {
  over_seeds("3 images, period", 3, only({TactileParameter::period}), 21, 45);
}

// Four images: periods within 3 steps (a narrow band) and patterns.
TEST(SeparationSearch, FourImagesNarrowPeriodAndPatternWithinTenPercentOfExhaustive) {
  over_seeds("4 images, period within 3 steps and pattern", 4, only({TactileParameter::period, TactileParameter::pattern}),
             51, 54, 3);
}

TEST(SeparationSearch, ADistinctSetIsLeftAlone) {
  test::AnalyticSpace space({{{20, 0, 0}}, {{20, 10, 0}}, {{20, 20, 0}}});
  study::SeparationRequest q;
  q.vary = study::all_tactile_parameters();
  const auto o = study::run_separation_search(space, q);
  EXPECT_TRUE(o.reached);
  EXPECT_EQ(o.total_change_jnd, 0.0);
  for (const SeparationSetting& s : o.settings) EXPECT_EQ(s, SeparationSetting{});
}

TEST(SeparationSearch, KeepAndVaryAreObeyedExactly) {
  for (unsigned seed = 31; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    test::AnalyticSpace space(confused_set(rng, 5));
    study::SeparationRequest q;
    q.vary = only({TactileParameter::period, TactileParameter::gain});
    q.keep = {false, true, false, false, true};
    const auto o = study::run_separation_search(space, q);
    for (std::size_t i = 0; i < o.settings.size(); ++i) {
      for (std::size_t p = 0; p < study::kTactileParameterCount; ++p) {
        if (q.keep[i] || !q.vary[p]) {
          EXPECT_EQ(o.settings[i][p], 0) << "seed " << seed << " image " << i << " parameter " << p;
        }
      }
    }
  }
}

TEST(SeparationSearch, StaysWithinTheAllowedSteps) {
  std::mt19937 rng(51);
  test::AnalyticSpace space(confused_set(rng, 6));
  space.period_limit = 2;  // a narrow band
  study::SeparationRequest q;
  q.vary = only({TactileParameter::period});
  const auto o = study::run_separation_search(space, q);
  for (const SeparationSetting& s : o.settings) EXPECT_LE(std::abs(s[kPeriod]), 2);
}

// Identification along one dimension saturates: eight images of one texture spread over the
// whole period range cannot all reach 90 %, while period, pattern and gain together can.
TEST(SeparationSearch, OneDimensionOutOfReachSeveralReach) {
  std::vector<test::AnalyticImage> same(8, test::AnalyticImage{{20.0, 10.0, 0.0}});
  study::SeparationRequest q;
  q.vary = only({TactileParameter::period});
  test::AnalyticSpace one(same);
  const auto narrow = study::run_separation_search(one, q);
  EXPECT_FALSE(narrow.reached);
  EXPECT_GT(narrow.shortfall, 0.0);
  q.vary = only({TactileParameter::period, TactileParameter::pattern, TactileParameter::gain});
  test::AnalyticSpace several(same);
  const auto wide = study::run_separation_search(several, q);
  EXPECT_TRUE(wide.reached);
  for (const double p : wide.identified) EXPECT_GE(p, 0.9 - 1e-12);
  (void)kGain;
  (void)kPattern;
}

TEST(SeparationSearch, IsDeterministic) {
  std::mt19937 rng(61);
  const auto images = confused_set(rng, 5);
  study::SeparationRequest q;
  q.vary = study::all_tactile_parameters();
  test::AnalyticSpace a(images), b(images);
  const auto x = study::run_separation_search(a, q);
  const auto y = study::run_separation_search(b, q);
  EXPECT_EQ(x.settings, y.settings);
  EXPECT_EQ(x.total_change_jnd, y.total_change_jnd);
}

}  // namespace
}  // namespace vimg
