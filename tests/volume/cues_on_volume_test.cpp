// The vibrotactile shaders over volume data: the transition cue located at the isosurface at any
// probe speed, roughness frequency v * omega / 2 pi with omega from the data, data-driven amplitude.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "primitives/cues/roughness_shader.hpp"
#include "primitives/cues/transition_cue_shader.hpp"
#include "primitives/volume/data_fields.hpp"
#include "primitives/volume/modulated_shader.hpp"
#include "primitives/volume/scalar_grid.hpp"
#include "tests/volume/analytic_fields.hpp"

namespace vimg {
namespace {

// A grid of Lambda = 1000 * (n . x) + offset: its isosurface 0 is a tilted plane.
std::shared_ptr<const ScalarGrid> tilted_plane_grid(const Vec3& n, double offset) {
  GridGeometry g;
  g.size = {41, 41, 41};
  g.origin_m = {-0.04, -0.04, -0.04};
  g.spacing_m = {0.002, 0.002, 0.002};
  std::vector<float> v(g.size.count());
  for (int k = 0; k < 41; ++k)
    for (int j = 0; j < 41; ++j)
      for (int i = 0; i < 41; ++i)
        v[g.linear_index(i, j, k)] = static_cast<float>(1000.0 * dot(n, g.voxel_to_world({double(i), double(j), double(k)})) + offset);
  return std::make_shared<const ScalarGrid>(g, std::move(v));
}

TEST(TransitionCueOnVolume, StartsWithin0p1mmOfThePlaneAtSpeedsUpTo0p5mPerS) {
  const Vec3 n = normalized(Vec3{0.2, -0.1, 1.0});
  const double offset = 3.3;  // plane at n . x = -3.3 mm
  const auto grid = tilted_plane_grid(n, offset);
  TransitionCueParams p;
  const TransitionCueShader cue(std::make_shared<VolumeValueField>(grid), p);
  const double rate = 1000.0;
  for (double speed : {0.01, 0.05, 0.2, 0.35, 0.5}) {
    ShaderState state;
    cue.begin_contact(state);
    const Vec3 start{0.003, 0.002, -0.03};
    const Vec3 dir = normalized(Vec3{0.1, 0.05, 1.0});
    InteractionState s;
    s.position_m = start;
    bool fired = false;
    const int max_steps = static_cast<int>(0.06 / (speed / rate));
    for (int step = 0; step < max_steps && !fired; ++step) {
      s.previous_position_m = s.position_m;
      s.position_m = start + dir * (speed * (step + 1) / rate);
      s.velocity_m_per_s = dir * speed;
      s.time_s = (step + 1) / rate;
      s.dt_s = 1.0 / rate;
      cue.force_N(s, state);
      Vec3 where;
      double when = 0.0;
      if (cue.last_crossing(state, where, when)) {
        fired = true;
        const double distance_to_plane_mm = std::abs(dot(n, where) * 1000.0 + offset);
        EXPECT_LT(distance_to_plane_mm, 0.1) << "speed " << speed;
        // ...and the cue's time origin is when the probe was there.
        const double expected_time = norm(where - start) / speed;
        EXPECT_NEAR(when, expected_time, 0.1e-3 / speed) << "speed " << speed;
      }
    }
    EXPECT_TRUE(fired) << "speed " << speed;
  }
}

TEST(RoughnessOnVolume, FrequencyIsSpeedTimesOmegaOver2Pi) {
  // Lambda = 1000 x; omega from the data: value -> 2 pi / period with period 1 mm at Lambda <= 0.
  auto field = std::make_shared<const testing::LinearScalar>(Vec3{1000.0, 0.0, 0.0}, 0.0);
  auto omega = std::make_shared<MappedSpatialFrequency>(field, TransferFunction({{0.0, 0.001}}),
                                                        MappedSpatialFrequency::Output::period_m);
  RoughnessParams params;
  params.direction = {0.0, 0.0, 1.0};
  params.amplitude_N = 0.5;
  params.full_amplitude_speed_m_per_s = 0.03;
  const RoughnessShader roughness(omega, params);
  const double rate = 8000.0;
  for (double speed : {0.02, 0.05, 0.1}) {
    ShaderState state;
    roughness.begin_contact(state);
    InteractionState s;
    s.position_m = {0.0, -0.01, 0.0};
    int crossings = 0;
    double last = 0.0;
    const int steps = static_cast<int>(rate);  // one second
    for (int i = 0; i < steps; ++i) {
      s.previous_position_m = s.position_m;
      s.position_m = Vec3{0.0, -0.01 + speed * (i + 1) / rate, 0.0};
      s.velocity_m_per_s = {0.0, speed, 0.0};
      s.dt_s = 1.0 / rate;
      s.time_s = (i + 1) / rate;
      const double f = roughness.force_N(s, state).z;
      if (last != 0.0 && f != 0.0 && (f > 0.0) != (last > 0.0)) ++crossings;
      if (f != 0.0) last = f;
    }
    const double expected_hz = speed * (2.0 * std::numbers::pi / 0.001) / (2.0 * std::numbers::pi);
    EXPECT_NEAR(crossings / 2.0, expected_hz, 1.0) << "speed " << speed;
  }
}

TEST(ModulatedShader, ScalesTheInnerForceByTheDataMappedGain) {
  auto field = std::make_shared<const testing::LinearScalar>(Vec3{0.0, 0.0, 1000.0}, 0.0);  // mm of z
  auto gain = std::make_shared<MappedValueField>(field, TransferFunction({{-20.0, 0.6}, {0.0, 0.3}, {20.0, 0.6}}));
  EXPECT_NEAR(gain->value({0, 0, -0.030}), 0.6, 1e-12);
  EXPECT_NEAR(gain->value({0, 0, -0.010}), 0.45, 1e-12);
  EXPECT_NEAR(gain->value({0, 0, 0.0}), 0.3, 1e-12);
  auto omega = std::make_shared<ConstantSpatialFrequency>(2000.0);
  RoughnessParams params;
  params.amplitude_N = 1.0;
  auto inner = std::make_shared<RoughnessShader>(omega, params);
  const ModulatedShader shader(inner, gain);
  ShaderState a, b;
  shader.begin_contact(a);
  inner->begin_contact(b);
  InteractionState s;
  s.position_m = {0.0, 0.0, -0.010};
  for (int i = 0; i < 50; ++i) {
    s.previous_position_m = s.position_m;
    s.position_m += Vec3{0.0001, 0.0, 0.0};
    s.velocity_m_per_s = {0.1, 0.0, 0.0};
    s.dt_s = 0.001;
    s.time_s += 0.001;
    const Vec3 fa = shader.force_N(s, a), fb = inner->force_N(s, b);
    EXPECT_NEAR(fa.z, 0.45 * fb.z, 1e-12);
  }
}

TEST(TransferFunction, PiecewiseLinearAndClampedAtTheEnds) {
  const TransferFunction f({{-1.0, 10.0}, {0.0, 0.0}, {2.0, 4.0}});
  EXPECT_EQ(f(-5.0), 10.0);
  EXPECT_EQ(f(9.0), 4.0);
  EXPECT_NEAR(f(-0.25), 2.5, 1e-12);
  EXPECT_NEAR(f(1.5), 3.0, 1e-12);
  EXPECT_EQ(f(std::nan("")), 10.0);
  EXPECT_EQ(TransferFunction()(3.0), 0.0);
}

}  // namespace
}  // namespace vimg
