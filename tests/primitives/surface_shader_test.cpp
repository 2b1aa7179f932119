#include "primitives/touch/surface_shader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "render_helper.hpp"

namespace vimg {
namespace {

using test::render;
using test::straight_path;

Surface big_rect(SurfacePattern pattern, double period_mm) {
  Surface s;
  s.shape = SurfaceShape::rect;
  s.x_mm = -10.0;
  s.y_mm = -50.0;
  s.width_mm = 400.0;
  s.height_mm = 100.0;
  s.period_mm = period_mm;
  s.relief_mm = 0.5;
  s.pattern = pattern;
  return s;
}

Surface big_polygon(SurfacePattern pattern, double period_mm) {
  Surface s = big_rect(pattern, period_mm);
  s.shape = SurfaceShape::polygon;
  s.points = {{-10, -50}, {390, -60}, {420, 0}, {390, 60}, {-10, 50}, {40, 0}};
  return s;
}

Surface big_ellipse(SurfacePattern pattern, double period_mm) {
  Surface s = big_rect(pattern, period_mm);
  s.shape = SurfaceShape::ellipse;
  s.cx_mm = 190.0;
  s.cy_mm = 0.0;
  s.rx_mm = 230.0;
  s.ry_mm = 40.0;
  return s;
}

struct Case {
  SurfacePattern pattern;
  int shape;  // 0 rect, 1 ellipse, 2 polygon
};

class SurfaceFrequency : public ::testing::TestWithParam<Case> {};

TEST_P(SurfaceFrequency, DominantFrequencyIsSpeedOverPeriod) {
  const Case c = GetParam();
  for (const double period_mm : {1.0, 2.5}) {
    const Surface surface = c.shape == 0   ? big_rect(c.pattern, period_mm)
                            : c.shape == 1 ? big_ellipse(c.pattern, period_mm)
                                           : big_polygon(c.pattern, period_mm);
    const SurfaceShader shader(surface, TouchContext{});
    for (const double v : {0.03, 0.07, 0.2, 0.45}) {
      const double expected = v / (period_mm * 1e-3);
      if (expected < 20.0 || expected > 500.0) continue;
      const auto r = render(shader, straight_path({0.05, 0.0, 0}, {v, 0, 0}), std::min(0.5, 0.3 / v));
      const auto crossings = test::zero_crossings(r, 0.0, 10.0);
      ASSERT_GE(crossings.size(), 10u);
      EXPECT_NEAR(test::crossing_frequency_hz(crossings), expected, 0.01 * expected)
          << "v=" << v << " period=" << period_mm;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PatternsAndShapes, SurfaceFrequency,
                         ::testing::Values(Case{SurfacePattern::sine, 0}, Case{SurfacePattern::square, 0},
                                           Case{SurfacePattern::triangle, 0}, Case{SurfacePattern::sine, 1},
                                           Case{SurfacePattern::triangle, 2}, Case{SurfacePattern::square, 2}));

TEST(SurfaceShader, FrequencyFollowsSpeedAlongCurvedPaths) {
  // A circle of radius 20 mm at 0.1 m/s inside the big rect: the speed is constant, so is f.
  const SurfaceShader shader(big_rect(SurfacePattern::sine, 2.0), TouchContext{});
  const double radius = 0.02, v = 0.1, w = v / radius;
  const test::Path circle = [=](double t) {
    return test::PathPoint{{0.05 + radius * std::cos(w * t), radius * std::sin(w * t), 0},
                           {-v * std::sin(w * t), v * std::cos(w * t), 0}, 1.0};
  };
  const auto r = render(shader, circle, 0.5);
  EXPECT_NEAR(test::crossing_frequency_hz(test::zero_crossings(r, 0, 1)), 50.0, 0.5);
}

TEST(SurfaceShader, PatternsHaveTheirShapes) {
  // Sampled over one slow period, each pattern's mean |value| tells it apart: sine 2/pi,
  // square 1, triangle 1/2 (full speed, full deformation).
  const double expected[] = {2.0 / std::numbers::pi, 1.0, 0.5};
  const SurfacePattern patterns[] = {SurfacePattern::sine, SurfacePattern::square, SurfacePattern::triangle};
  for (int i = 0; i < 3; ++i) {
    const SurfaceShader shader(big_rect(patterns[i], 2.0), TouchContext{});
    const auto r = render(shader, straight_path({0.0, 0.0, 0}, {0.1, 0, 0}), 0.2);  // 10 periods
    double sum = 0.0;
    for (double d : r.drive) sum += std::abs(d);
    EXPECT_NEAR(sum / static_cast<double>(r.drive.size()), expected[i], 0.01) << i;
    EXPECT_LE(test::max_abs(r), 1.0);
  }
}

TEST(SurfaceShader, AmplitudeIsClippedDeformationOverReliefTimesSpeedFade) {
  TouchContext context;
  context.max_deformation_m = 0.001;
  context.full_speed_m_per_s = 0.1;
  Surface surface = big_rect(SurfacePattern::square, 2.0);
  surface.relief_mm = 0.5;
  surface.gain = 0.8;
  const SurfaceShader shader(surface, context);
  for (const double pressure : {0.1, 0.25, 0.5, 0.9}) {
    for (const double v : {0.02, 0.05, 0.1, 0.3}) {
      const test::Path path = [=](double t) { return test::PathPoint{{v * t, 0, 0}, {v, 0, 0}, pressure}; };
      const auto r = render(shader, path, 0.05);
      const double deformation_mm = pressure * 1.0;
      const double expected = 0.8 * std::min(deformation_mm, 0.5) / 0.5 * std::min(1.0, v / 0.1);
      EXPECT_NEAR(test::max_abs(r), expected, 1e-12) << "pressure=" << pressure << " v=" << v;
    }
  }
}

TEST(SurfaceShader, StillFingerFadesBelowOnePercentWithin50ms) {
  const SurfaceShader shader(big_rect(SurfacePattern::square, 2.0), TouchContext{});
  // Decelerates linearly from 0.15 m/s to rest over 20 ms starting at t = 0.1 s, then stays.
  const test::Path path = [](double t) {
    const double v0 = 0.15, t0 = 0.1, ramp = 0.02;
    if (t < t0) return test::PathPoint{{v0 * t, 0, 0}, {v0, 0, 0}, 1.0};
    const double u = std::min(t - t0, ramp);
    const double v = v0 * (1.0 - u / ramp);
    const double x = v0 * t0 + v0 * u - 0.5 * v0 / ramp * u * u;
    return test::PathPoint{{x, 0, 0}, {v, 0, 0}, 1.0};
  };
  const auto r = render(shader, path, 0.3);
  EXPECT_GT(test::max_abs(r, 0.0, 0.1), 0.9);
  EXPECT_LT(test::max_abs(r, 0.15, 0.3), 0.01);
}

TEST(SurfaceShader, PhaseAdvancesOnlyWithDistanceTravelledInside) {
  // A finger sliding in and out of a narrow rect, 10 mm wide, period 2 mm, at 0.1 m/s: inside it
  // sees whole periods and the phase resumes where it left (no jump on re-entry).
  Surface surface = big_rect(SurfacePattern::sine, 2.0);
  surface.x_mm = 0.0;
  surface.width_mm = 10.0;
  const SurfaceShader shader(surface, TouchContext{});
  const auto r = render(shader, straight_path({-0.005, 0.0, 0}, {0.1, 0, 0}), 0.2);
  // Inside 50..150 ms: 10 mm / 2 mm = 5 periods -> 10 sign changes (+/- one at the ends).
  const auto crossings = test::zero_crossings(r, 0.0, 1.0);
  EXPECT_NEAR(static_cast<double>(crossings.size()), 9.0, 1.0);
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    const double x = -0.005 + 0.1 * r.time_s[k];
    if (x < -1e-9 || x > 0.010 + 1e-9) {
      ASSERT_EQ(r.drive[k], 0.0) << "t=" << r.time_s[k];
    } else {
      // Phase = 2 pi x / period exactly, since the finger entered at x = 0.
      EXPECT_NEAR(r.drive[k], std::sin(2.0 * std::numbers::pi * x / 0.002), 1e-6);
    }
  }
}

}  // namespace
}  // namespace vimg
