#include <gtest/gtest.h>

#include "player/haptic/haptic_cycle.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

using testing::AnchorSpringShader;
using testing::ConstantForceShader;

std::unique_ptr<HapticScene> scene_of(std::vector<std::shared_ptr<const ForceShader>> kin,
                                      std::vector<std::shared_ptr<const ForceShader>> vib = {}) {
  return std::make_unique<HapticScene>(DeviceProfile{}, std::vector<std::shared_ptr<const void>>{}, std::move(kin), std::move(vib));
}

ProbeSample at(const Vec3& p) {
  ProbeSample s;
  s.position_m = p;
  return s;
}

HapticCycleConfig no_gate(double max_force) { return {max_force, 1e9, 0.0, 0.1}; }

TEST(HapticCycle, SumsKinaestheticAndVibrotactileThenClampsOnce) {
  auto scene = scene_of({std::make_shared<ConstantForceShader>(Vec3{3.0, 0.0, 0.0})},
                        {std::make_shared<ConstantForceShader>(Vec3{-1.0, 4.0, 0.0})});
  HapticCycle cycle(no_gate(2.0));
  cycle.set_scene(scene.get(), 0.0);
  const CycleOutput out = cycle.step(at({}), 0.0);
  EXPECT_EQ(out.parts.kinaesthetic_N, (Vec3{3.0, 0.0, 0.0}));
  EXPECT_EQ(out.parts.vibrotactile_N, (Vec3{-1.0, 4.0, 0.0}));
  // (2, 4, 0) has magnitude sqrt(20) > 2: scaled to 2 along the same direction.
  EXPECT_NEAR(norm(out.total_N), 2.0, 1e-12);
  EXPECT_NEAR(out.total_N.y / out.total_N.x, 2.0, 1e-12);
  EXPECT_EQ(out.sent_N, out.total_N);

  auto small = scene_of({std::make_shared<ConstantForceShader>(Vec3{0.5, 0.0, 0.0})},
                        {std::make_shared<ConstantForceShader>(Vec3{-0.25, 0.5, 0.0})});
  HapticCycle below(no_gate(2.0));
  below.set_scene(small.get(), 0.0);
  EXPECT_EQ(below.step(at({}), 0.0).total_N, (Vec3{0.25, 0.5, 0.0}));
}

TEST(HapticCycle, NoSceneSendsZero) {
  HapticCycle cycle(no_gate(3.0));
  EXPECT_EQ(cycle.step(at({0.01, 0, 0}), 0.0).sent_N, Vec3{});
}

TEST(HapticCycle, StartUpWaitsForASmallForceThenRampsWithoutSteps) {
  // A spring to the origin; the probe starts 10 mm away (3 N) and moves in to rest.
  auto scene = scene_of({std::make_shared<AnchorSpringShader>(Vec3{}, 300.0)});
  const HapticCycleConfig config{3.3, 0.2, 0.5, 0.1};
  HapticCycle cycle(config);
  cycle.set_scene(scene.get(), 0.0);
  Vec3 last_sent;
  bool released = false;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i * 1e-3;
    const double x = std::max(0.0, 0.010 - 0.02 * t);  // reaches the anchor at 0.5 s
    const CycleOutput out = cycle.step(at({x, 0.0, 0.0}), t);
    if (out.gated) {
      EXPECT_EQ(out.sent_N, Vec3{}) << t;
      EXPECT_GE(norm(out.total_N), 0.2) << t;
    } else {
      if (!released) {
        EXPECT_LT(norm(out.total_N), 0.2);
      }
      released = true;
    }
    EXPECT_LE(norm(out.sent_N - last_sent), 0.2) << "force step at " << t;
    last_sent = out.sent_N;
  }
  EXPECT_TRUE(released);
}

TEST(HapticCycle, WithoutTheGateTheFirstCycleWouldStepFullForce) {
  // The counterpart of the gating test: the same start renders 3 N at once without it.
  auto scene = scene_of({std::make_shared<AnchorSpringShader>(Vec3{}, 300.0)});
  HapticCycle cycle(no_gate(3.3));
  cycle.set_scene(scene.get(), 0.0);
  EXPECT_NEAR(norm(cycle.step(at({0.010, 0.0, 0.0}), 0.0).sent_N), 3.0, 1e-12);
}

TEST(HapticCycle, RampsInLinearlyOverTheRampTime) {
  auto scene = scene_of({std::make_shared<ConstantForceShader>(Vec3{0.0, 0.0, 0.1})});
  HapticCycle cycle({3.3, 0.2, 0.5, 0.1});
  cycle.set_scene(scene.get(), 0.0);
  for (int i = 0; i <= 700; ++i) {
    const double t = i * 1e-3;
    const CycleOutput out = cycle.step(at({}), t);
    EXPECT_NEAR(out.sent_N.z, 0.1 * std::min(1.0, t / 0.5), 1e-12);
  }
}

TEST(HapticCycle, SceneChangesCrossFadeThenRetireTheOldScene) {
  auto a = scene_of({std::make_shared<ConstantForceShader>(Vec3{1.0, 0.0, 0.0})});
  auto b = scene_of({std::make_shared<ConstantForceShader>(Vec3{0.0, 1.0, 0.0})});
  HapticCycle cycle(no_gate(3.3));
  cycle.set_scene(a.get(), 0.0);
  cycle.step(at({}), 0.0);
  cycle.set_scene(b.get(), 1.0);
  EXPECT_TRUE(cycle.fading());
  for (int i = 0; i <= 100; ++i) {
    const double t = 1.0 + i * 1e-3;
    const double w = std::min(1.0, (t - 1.0) / 0.1);
    const Vec3 f = cycle.step(at({}), t).total_N;
    EXPECT_NEAR(f.x, 1.0 - w, 1e-9) << t;
    EXPECT_NEAR(f.y, w, 1e-9) << t;
  }
  EXPECT_FALSE(cycle.fading());
  EXPECT_EQ(cycle.take_retired(), a.get());
  EXPECT_EQ(cycle.take_retired(), nullptr);
}

}  // namespace
}  // namespace vimg
