#include <gtest/gtest.h>

#include <random>

#include "primitives/kinaesthetic/combined_feedback.hpp"
#include "primitives/kinaesthetic/gradient_force.hpp"
#include "primitives/kinaesthetic/vector_guidance.hpp"
#include "primitives/kinaesthetic/virtual_coupling.hpp"
#include "primitives/kinaesthetic/yielding_surface.hpp"
#include "tests/volume/analytic_fields.hpp"

namespace vimg {
namespace {

using testing::LinearScalar;
using testing::QuadraticScalar;
using testing::UniformVector;

InteractionState at(const Vec3& p, const Vec3& v = {}, double dt = 1e-3) {
  InteractionState s;
  s.position_m = p;
  s.previous_position_m = p - v * dt;
  s.velocity_m_per_s = v;
  s.dt_s = dt;
  return s;
}

void expect_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(GradientForce, IsCTimesTheGradientAtTheProbe) {
  const QuadraticScalar field(250.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (double c : {0.01, -0.004}) {
    const GradientForceShader shader(field, c);
    ShaderState state;
    shader.begin_contact(state);
    for (int n = 0; n < 100; ++n) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      expect_near(shader.force_N(at(p), state), c * 2.0 * 250.0 * p, 1e-12);
    }
  }
}

TEST(VirtualCoupling, MatchesEquation3) {
  const CouplingParams k{400.0, 0.7};
  const VirtualCouplingShader shader(k);
  ShaderState state;
  shader.begin_contact(state);
  InteractionState s = at({0.01, -0.02, 0.003}, {0.1, 0.0, -0.2});
  s.proxy_position_m = {0.012, -0.018, 0.0};
  s.proxy_velocity_m_per_s = {0.05, 0.01, 0.0};
  const Vec3 expected = -400.0 * (s.position_m - s.proxy_position_m) - 0.7 * (s.velocity_m_per_s - s.proxy_velocity_m_per_s);
  expect_near(shader.force_N(s, state), expected, 1e-12);
}

// A surface whose normal is z: Lambda = 1000 z.
struct SurfaceFixture {
  LinearScalar field{{0.0, 0.0, 1000.0}, 0.0};
  YieldingSurfaceParams params{{500.0, 0.0}, 2.0, 0.4, 1.0};
  YieldingSurfaceShader shader{field, params};
  ShaderState state;
  SurfaceFixture() { shader.begin_contact(state); }
  Vec3 step(const Vec3& p) { return shader.force_N(at(p), state); }
};

TEST(YieldingSurface, SpringAcrossTheSurfaceBelowTheYieldForce) {
  SurfaceFixture f;
  EXPECT_EQ(f.step({0, 0, 0}), Vec3{});  // the proxy starts on the probe
  for (double depth : {0.0005, 0.001, 0.0039}) {
    const Vec3 force = f.step({0, 0, -depth});
    expect_near(force, {0, 0, 500.0 * depth}, 1e-9);  // f = -k_s (x_probe - x_proxy)
  }
}

TEST(YieldingSurface, GivesWayAboveTheYieldForce) {
  SurfaceFixture f;
  f.step({0, 0, 0});
  for (double depth = 0.0; depth < 0.02; depth += 0.0002) {
    const Vec3 force = f.step({0, 0, -depth});
    EXPECT_LE(norm(force), 2.0 + 1e-9);
    if (500.0 * depth >= 2.0) {
      EXPECT_NEAR(force.z, 2.0, 1e-9);
    }
  }
  // After pushing through, pulling back by less than the yield distance feels the surface again.
  const Vec3 back = f.step({0, 0, -0.02 + 0.001});
  EXPECT_NEAR(back.z, 2.0 - 0.5, 1e-9);
}

TEST(YieldingSurface, FrictionLimitsTheTangentialForceToMuTimesTheNormalForce) {
  SurfaceFixture f;
  f.step({0, 0, 0});
  const double depth = 0.002;  // normal force 1 N, below the yield force
  f.step({0, 0, -depth});
  // Sticking: small tangential displacement gives a spring force.
  Vec3 force = f.step({0.0005, 0, -depth});
  EXPECT_NEAR(force.x, -500.0 * 0.0005, 1e-9);
  EXPECT_NEAR(force.z, 1.0, 1e-9);
  // Sliding: the tangential force saturates at mu * 1 N.
  for (double x = 0.001; x < 0.03; x += 0.001) {
    force = f.step({x, 0, -depth});
    EXPECT_NEAR(force.x, -0.4, 1e-9);
    EXPECT_NEAR(force.z, 1.0, 1e-9);
  }
}

TEST(YieldingSurface, FreeSpaceWhereTheGradientIsWeak) {
  LinearScalar weak({0.0, 0.0, 0.5}, 0.0);
  YieldingSurfaceParams p;
  p.min_gradient_per_m = 1.0;
  p.coupling.damping_N_s_per_m = 0.0;
  const YieldingSurfaceShader shader(weak, p);
  ShaderState state;
  shader.begin_contact(state);
  for (double z = 0.0; z < 0.01; z += 0.001) EXPECT_EQ(shader.force_N(at({0, 0, -z}), state), Vec3{});
}

TEST(YieldingSurface, DampingActsOnTheRelativeVelocity) {
  LinearScalar field({0.0, 0.0, 1000.0}, 0.0);
  YieldingSurfaceParams p{{500.0, 2.0}, 10.0, 0.0, 1.0};
  const YieldingSurfaceShader shader(field, p);
  ShaderState state;
  shader.begin_contact(state);
  shader.force_N(at({0, 0, 0}), state);
  // The probe moves into the surface at 0.1 m/s; the proxy stays (below yield): f = -k d - k_d v.
  const Vec3 force = shader.force_N(at({0, 0, -0.0001}, {0, 0, -0.1}), state);
  EXPECT_NEAR(force.z, 500.0 * 0.0001 + 2.0 * 0.1, 1e-9);
}

TEST(VectorGuidance, FreeAlongTheFieldResistedAcrossIt) {
  const Vec3 direction = normalized(Vec3{1.0, 0.0, 1.0});
  UniformVector field(direction * 3.0);
  VectorGuidanceParams p{{400.0, 0.0}, 1.2, 0.0, 1e-6};
  const VectorGuidanceShader shader(field, p);
  ShaderState state;
  shader.begin_contact(state);
  shader.force_N(at({0, 0, 0}), state);
  for (double s = 0.0; s < 0.05; s += 0.001) {
    EXPECT_LT(norm(shader.force_N(at(direction * s), state)), 1e-12);
  }
  const Vec3 base = direction * 0.049;
  const Vec3 across = normalized(Vec3{1.0, 0.0, -1.0});
  // Across the field: a spring up to the resistance force, then the proxy is dragged along.
  Vec3 force = shader.force_N(at(base + across * 0.002), state);
  expect_near(force, across * (-400.0 * 0.002), 1e-9);
  for (double d = 0.003; d < 0.02; d += 0.001) {
    force = shader.force_N(at(base + across * d), state);
    expect_near(force, across * -1.2, 1e-9);
  }
}

TEST(VectorGuidance, FollowModePullsAlongTheField) {
  UniformVector field({0.0, 2.0, 0.0});
  VectorGuidanceParams p{{400.0, 0.0}, 1.0, 0.25, 1e-6};
  const VectorGuidanceShader shader(field, p);
  ShaderState state;
  shader.begin_contact(state);
  expect_near(shader.force_N(at({0.01, 0.0, 0.0}), state), {0.0, 0.25, 0.0}, 1e-12);
}

TEST(CombinedFeedback, IsTheVectorSumOfKinaestheticAndVibrotactileParts_Eq7) {
  const QuadraticScalar field(100.0);
  const GradientForceShader a(field, 0.02), b(field, -0.005);
  const VirtualCouplingShader coupling({300.0, 0.4});
  CombinedFeedback feedback({&coupling, &a}, {&b});
  InteractionState s = at({0.01, 0.02, -0.01}, {0.1, 0, 0});
  s.proxy_position_m = {0.011, 0.02, -0.01};
  const FeedbackParts parts = feedback.evaluate(s);
  ShaderState scratch;
  const Vec3 kin = coupling.force_N(s, scratch) + a.force_N(s, scratch);
  const Vec3 vib = b.force_N(s, scratch);
  expect_near(parts.kinaesthetic_N, kin, 1e-12);
  expect_near(parts.vibrotactile_N, vib, 1e-12);
  expect_near(parts.total_N(), kin + vib, 1e-12);
}

}  // namespace
}  // namespace vimg
