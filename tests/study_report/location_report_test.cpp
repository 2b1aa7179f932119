// The location study's statistics with the volume paper's figures (section 5.5.2; issue 21): 56 marks
// at 14.1 +- 9.7 mm give the 99 % interval 10.7-17.6 mm and 7.6 +- 7.0 mm give 5.1-10.1 mm, to the
// paper's rounding; chance in closed form against a quadrature; the per-metaphor report.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "study/report_chance.hpp"
#include "study/report_location.hpp"
#include "study/statistics.hpp"

namespace vimg::study {
namespace {

double round1(double x) { return std::round(x * 10.0) / 10.0; }

TEST(LocationFigures, TransitionCueIntervalIsThePapers) {
  const auto ci = t_interval_of_mean(7.6, 7.0, 56, 0.99);
  ASSERT_TRUE(ci);
  EXPECT_DOUBLE_EQ(round1(ci->lower), 5.1);
  EXPECT_DOUBLE_EQ(round1(ci->upper), 10.1);
  EXPECT_NEAR(ci->lower, 5.104, 0.001);  // 7.6 -+ t(0.995, 55) * 7.0 / sqrt(56), t = 2.6682
  EXPECT_NEAR(ci->upper, 10.096, 0.001);
}

// The paper prints 14.1 and 9.7, rounded; from those the interval is 10.64-17.56, which rounds to
// 10.6 where the paper says 10.7. Its unrounded mean was a little above 14.1: the paper's interval
// follows from figures that round to its own (mean 14.14, SD 9.7), and the rounded ones stay
// within what their rounding allows.
TEST(LocationFigures, RoughnessIntervalIsThePapersToItsRounding) {
  const auto ci = t_interval_of_mean(14.1, 9.7, 56, 0.99);
  ASSERT_TRUE(ci);
  const double t_quantile = 2.6682;  // t(0.995, 55), tables
  const double slack = 0.05 + 0.05 + 0.05 * t_quantile / std::sqrt(56.0);  // output, mean and SD rounding
  EXPECT_NEAR(ci->lower, 10.7, slack);
  EXPECT_NEAR(ci->upper, 17.6, slack);
  const auto unrounded = t_interval_of_mean(14.14, 9.7, 56, 0.99);
  ASSERT_TRUE(unrounded);
  EXPECT_DOUBLE_EQ(round1(unrounded->lower), 10.7);
  EXPECT_DOUBLE_EQ(round1(unrounded->upper), 17.6);
  EXPECT_DOUBLE_EQ(round1(14.14), 14.1);
}

TEST(LocationFigures, TheTQuantileHas55DegreesOfFreedom) {
  // The half-width over SD / sqrt(n) is the t quantile: 2.668 for 55 df (1.96 would be the normal's).
  const auto ci = t_interval_of_mean(0.0, std::sqrt(56.0), 56, 0.99);
  ASSERT_TRUE(ci);
  EXPECT_NEAR(ci->upper, 2.6682, 1e-4);
}

// Chance in closed form against a midpoint quadrature of the same integral.
double quadrature_mm(const Workspace& w, double x, double z) {
  const int nx = 1600, nz = 1200;
  double sum = 0.0;
  for (int i = 0; i < nx; ++i) {
    for (int k = 0; k < nz; ++k) {
      const double u = w.x_min_mm + (w.x_max_mm - w.x_min_mm) * (i + 0.5) / nx;
      const double v = w.z_min_mm + (w.z_max_mm - w.z_min_mm) * (k + 0.5) / nz;
      sum += std::hypot(u - x, v - z);
    }
  }
  return sum / (static_cast<double>(nx) * nz);
}

TEST(Chance, StudyWorkspaceIsTheDataSetsBox) {
  const Workspace w = study_workspace();
  EXPECT_NEAR(w.x_min_mm, -80.0, 1e-9);
  EXPECT_NEAR(w.x_max_mm, 80.0, 1e-9);
  EXPECT_NEAR(w.z_min_mm, -60.0, 1e-9);
  EXPECT_NEAR(w.z_max_mm, 60.0, 1e-9);
}

TEST(Chance, ClosedFormMatchesQuadratureInsideAndOutside) {
  const Workspace w = study_workspace();
  for (const auto& [x, z] : {std::pair{0.0, 0.0}, {30.0, -20.0}, {-80.0, 60.0}, {79.0, -59.0}, {120.0, 0.0}, {-200.0, 150.0}}) {
    EXPECT_NEAR(expected_uniform_distance_mm(w, x, z), quadrature_mm(w, x, z), 1e-3) << x << "," << z;
  }
}

TEST(Chance, KnownValues) {
  // The mean distance from a corner of the unit square: (sqrt 2 + ln(1 + sqrt 2)) / 3.
  const Workspace unit{0.0, 1.0, 0.0, 1.0};
  EXPECT_NEAR(expected_uniform_distance_mm(unit, 0.0, 0.0), (std::sqrt(2.0) + std::log(1.0 + std::sqrt(2.0))) / 3.0, 1e-14);
  // The study's box with the target at its centre: 53.9 mm, the paper's "about 53 mm".
  EXPECT_NEAR(expected_uniform_distance_mm(study_workspace(), 0.0, 0.0), 53.8955, 1e-4);
}

// Far outside (report_chance.hpp): beyond 10^4 workspace diagonals the expectation is the distance
// to the centre, which it approaches to within 1e-8 relative; an expansion of the integral for a
// point at distance D along x from the centre of the 160 x 120 mm box gives D + 600 / D mm (the
// mean of z^2 / 2D; z uniform over 120 mm), and in general D + (variance across the direction) / 2D. Either side of the switch (10^4 diagonals = 2e6 mm) and
// far beyond, where the closed form's cubes would overflow.
TEST(Chance, FarTargetsGiveTheDistanceToTheCentre) {
  const Workspace w = study_workspace();
  for (const double d : {1e5, 1.9e6, 2.1e6, 1e9, 1e120}) {
    const double expected = d + 600.0 / d;
    EXPECT_NEAR(expected_uniform_distance_mm(w, d, 0.0), expected, 1e-8 * expected) << d;
    // Along (-0.6, 0.8): the variance across that direction is 0.64 * 160^2/12 + 0.36 * 120^2/12.
    const double across = (0.64 * 160.0 * 160.0 / 12.0 + 0.36 * 120.0 * 120.0 / 12.0) / 2.0;
    EXPECT_NEAR(expected_uniform_distance_mm(w, -0.6 * d, 0.8 * d), d + across / d, 1e-8 * d) << d;
  }
}

LocationTrial trial(const std::string& participant, int number, LocationMetaphor m, double tx, double tz, double error) {
  LocationTrial t;
  t.participant = participant;
  t.trial = number;
  t.metaphor = m;
  t.target_x_mm = tx;
  t.target_z_mm = tz;
  t.error_mm = error;
  return t;
}

TEST(LocationReport, PerMetaphorChanceAndWelch) {
  using enum LocationMetaphor;
  const std::vector<LocationTrial> trials{
      trial("b", 1, transition_cue, 0, 0, 2.0),  trial("b", 2, transition_cue, 0, 0, 4.0), trial("a", 1, roughness, 0, 0, 10.0),
      trial("a", 2, roughness, 30, -20, 20.0),   trial("a", 3, transition_cue, 0, 0, 6.0), trial("b", 3, roughness, 0, 0, 30.0)};
  const LocationReport r = make_location_report(trials);
  ASSERT_EQ(r.metaphors.size(), 2u);
  EXPECT_EQ(r.metaphors[0].name, "roughness");  // roughness first, whatever the trials' order
  EXPECT_EQ(r.metaphors[1].name, "transitionCue");
  EXPECT_EQ(r.metaphors[0].n, 3u);
  EXPECT_DOUBLE_EQ(r.metaphors[0].mean_mm, 20.0);
  EXPECT_DOUBLE_EQ(*r.metaphors[0].sd_mm, 10.0);
  EXPECT_DOUBLE_EQ(r.metaphors[1].mean_mm, 4.0);
  EXPECT_DOUBLE_EQ(*r.metaphors[1].sd_mm, 2.0);
  // SciPy 1.10.1: t.interval(0.99, 2, loc=20, scale=10/sqrt(3)).
  ASSERT_TRUE(r.metaphors[0].ci99_mm);
  EXPECT_NEAR(r.metaphors[0].ci99_mm->lower, -37.301108937148754, 1e-9);
  EXPECT_NEAR(r.metaphors[0].ci99_mm->upper, 77.30110893714875, 1e-9);
  // Chance from the quadrature above, not from the closed form the report uses.
  const Workspace w = study_workspace();
  const double centre = quadrature_mm(w, 0, 0), off = quadrature_mm(w, 30, -20);
  EXPECT_NEAR(r.metaphors[0].chance_mm, (2 * centre + off) / 3, 1e-3);
  EXPECT_NEAR(r.metaphors[1].chance_mm, centre, 1e-3);
  EXPECT_NEAR(r.chance_mm, (5 * centre + off) / 6, 1e-3);
  ASSERT_EQ(r.metaphor_comparisons.size(), 1u);
  // Hand-worked: t = 16 / sqrt(100/3 + 4/3) = 2.7136, df = (104/3)^2 / ((100/3)^2/2 + (4/3)^2/2) = 2.1598.
  EXPECT_NEAR(r.metaphor_comparisons[0].welch->t, 16.0 / std::sqrt(104.0 / 3.0), 1e-12);
  EXPECT_NEAR(r.metaphor_comparisons[0].welch->df, (104.0 / 3) * (104.0 / 3) / ((10000.0 / 9 + 16.0 / 9) / 2), 1e-12);
  // SciPy 1.10.1: ttest_ind([10, 20, 30], [2, 4, 6], equal_var=False).pvalue.
  EXPECT_NEAR(r.metaphor_comparisons[0].welch->p, 0.10401031212071261, 1e-9);
  ASSERT_EQ(r.participants.size(), 2u);
  EXPECT_EQ(r.participants[0].participant, "a");
  EXPECT_DOUBLE_EQ(r.participants[0].metaphors[0].mean_mm, 15.0);
  EXPECT_EQ(r.participants[0].metaphors[1].n, 1u);
  EXPECT_DOUBLE_EQ(r.participants[1].metaphors[1].mean_mm, 3.0);
}

}  // namespace
}  // namespace vimg::study
