#include "primitives/touch/dot_shader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_helper.hpp"

namespace vimg {
namespace {

using test::render;
using test::straight_path;

TouchContext context_with_full_speed(double full_speed_m_per_s) {
  TouchContext c;
  c.full_speed_m_per_s = full_speed_m_per_s;
  return c;
}

// A finger moving along +x at speed v, offset from the centre by `offset` in y, starting 10 mm left.
struct Crossing {
  double radius_m, offset_m, speed_m_per_s;
  double entry_s() const { return (0.010 - half_chord()) / speed_m_per_s; }
  double exit_s() const { return (0.010 + half_chord()) / speed_m_per_s; }
  double half_chord() const { return std::sqrt(radius_m * radius_m - offset_m * offset_m); }
};

TEST(DotShader, DrivesExactlyWhileTheFingerIsWithinTheRadius) {
  for (const Crossing c : {Crossing{0.002, 0.0, 0.05}, Crossing{0.003, 0.002, 0.08}, Crossing{0.004, 0.001, 0.013}}) {
    const DotShader dot(Dot{0.0, 0.0, c.radius_m * 1e3, 1.0}, TouchContext{});
    const auto r = render(dot, straight_path({-0.010, c.offset_m, 0}, {c.speed_m_per_s, 0, 0}), 0.02 / c.speed_m_per_s);
    double first = -1, last = -1;
    for (std::size_t k = 0; k < r.drive.size(); ++k) {
      const double t = r.time_s[k];
      const bool inside = t >= c.entry_s() - 1e-9 && t <= c.exit_s() + 1e-9;
      if (r.drive[k] != 0.0) {
        EXPECT_TRUE(inside) << "drive outside the disc at t=" << t;
      } else if (t > c.entry_s() + 1e-9 && t < c.exit_s() - 1e-9) {
        // Silence inside is only allowed where the carrier itself crosses zero.
        EXPECT_LT(std::abs(std::sin(2.0 * std::numbers::pi * 175.0 * (t - c.entry_s()))), 1e-6) << "t=" << t;
      }
      if (r.active[k]) {
        EXPECT_TRUE(inside) << "active outside the disc at t=" << t;
        if (first < 0) first = t;
        last = t;
      }
    }
    const double chord_time = 2.0 * c.half_chord() / c.speed_m_per_s;
    // n samples inside measure a duration of n / rate, within one sample of the chord time.
    const double measured = (last - first) + 1.0 / r.sample_rate_hz;
    EXPECT_NEAR(measured, chord_time, 1.0 / r.sample_rate_hz + 1e-9);
  }
}

TEST(DotShader, CarrierIsAtTheActuatorResonance) {
  for (const double carrier : {150.0, 175.0, 235.0}) {
    TouchContext context;
    context.carrier_frequency_hz = carrier;
    const DotShader dot(Dot{0.0, 0.0, 5.0, 1.0}, context);
    const auto r = render(dot, straight_path({-0.006, 0, 0}, {0.01, 0, 0}), 1.2);
    const auto crossings = test::zero_crossings(r, 0.0, 2.0);
    ASSERT_GT(crossings.size(), 100u);
    EXPECT_NEAR(test::crossing_frequency_hz(crossings), carrier, 0.005 * carrier);
  }
}

TEST(DotShader, CarrierPhaseStartsAtTheExactEntryTime) {
  // Entry at 0.5 mm / 0.05 m/s = 10 ms exactly, between no particular samples of a 7 kHz rate.
  const DotShader dot(Dot{0.0, 0.0, 1.0, 1.0}, TouchContext{});
  const auto r = render(dot, straight_path({-0.0015, 0, 0}, {0.05, 0, 0}), 0.05, 7000.0);
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    if (r.drive[k] == 0.0) continue;
    const double expected = 0.5 * std::sin(2.0 * std::numbers::pi * 175.0 * (r.time_s[k] - 0.010));
    EXPECT_NEAR(r.drive[k], expected, 1e-9) << "t=" << r.time_s[k];
  }
}

TEST(DotShader, PeakDoesNotDecreaseWithSpeedAndSaturatesAtFullSpeed) {
  const TouchContext context = context_with_full_speed(0.1);
  const DotShader dot(Dot{0.0, 0.0, 5.0, 0.8}, context);
  double previous_peak = 0.0;
  for (double v = 0.005; v <= 0.1 + 1e-12; v += 0.005) {
    const auto r = render(dot, straight_path({-0.006, 0, 0}, {v, 0, 0}), 0.012 / v);
    const double peak = test::max_abs(r);
    EXPECT_GE(peak, previous_peak) << "v=" << v;
    EXPECT_NEAR(peak, 0.8 * v / 0.1, 0.01 * 0.8) << "f_N = m v / (m fullSpeed)";
    previous_peak = peak;
  }
  for (const double v : {0.2, 0.5}) {
    const auto r = render(dot, straight_path({-0.006, 0, 0}, {v, 0, 0}), 0.012 / v);
    EXPECT_LE(test::max_abs(r), 0.8 + 1e-12);
    EXPECT_GE(test::max_abs(r), 0.8 * 0.97);
  }
}

TEST(DotShader, EveryNewCrossingFiresAgain) {
  const DotShader dot(Dot{0.0, 0.0, 2.0, 1.0}, TouchContext{});
  // Back and forth across the dot: x(t) = 5 mm * sin(2 pi t / 0.4 s), three passes in 0.5 s.
  const test::Path path = [](double t) {
    const double w = 2.0 * std::numbers::pi / 0.4;
    return test::PathPoint{{0.005 * std::sin(w * t), 0, 0}, {0.005 * w * std::cos(w * t), 0, 0}, 1.0};
  };
  const auto r = render(dot, path, 0.5);
  int pulses = 0;
  bool on = false;
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    const bool inside = std::abs(0.005 * std::sin(2.0 * std::numbers::pi / 0.4 * r.time_s[k])) < 0.002;
    if (inside && !on) ++pulses;
    on = inside;
    if (!inside) {
      EXPECT_EQ(r.drive[k], 0.0);
    }
  }
  EXPECT_EQ(pulses, 3);
  EXPECT_GT(test::max_abs(r, 0.15, 0.25), 0.5);  // the second pass at t = 0.2 s fires too
  EXPECT_GT(test::max_abs(r, 0.35, 0.45), 0.5);
}

TEST(DotShader, SilentAndInactiveWhenTheFingerNeverEnters) {
  const DotShader dot(Dot{0.0, 0.0, 2.0, 1.0}, TouchContext{});
  const auto r = render(dot, straight_path({-0.010, 0.0021, 0}, {0.1, 0, 0}), 0.2);
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    EXPECT_EQ(r.drive[k], 0.0);
    EXPECT_FALSE(r.active[k]);
  }
}

TEST(DotShader, EmitsAlongTheActuatorAxisScaledByFullScale) {
  TouchContext context;
  context.axis = {1, 0, 0};
  context.full_scale_force_N = 2.5;
  const DotShader dot(Dot{0.0, 0.0, 5.0, 1.0}, context);
  ShaderState state;
  dot.begin_contact(state);
  InteractionState s;
  s.previous_position_m = {-0.006, 0, 0};
  s.position_m = {-0.004, 0, 0};
  s.velocity_m_per_s = {0.2, 0, 0};
  s.time_s = 0.01;
  s.dt_s = 0.01;
  const Vec3 f = dot.force_N(s, state);
  EXPECT_EQ(f.y, 0.0);
  EXPECT_EQ(f.z, 0.0);
  EXPECT_NEAR(f.x, 2.5 * std::sin(2.0 * std::numbers::pi * 175.0 * 0.005), 1e-12);
}

}  // namespace
}  // namespace vimg
