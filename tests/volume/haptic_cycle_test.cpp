// HapticCycle renders and cross-fades; clamping and gating are the SafetyStack's
// (safety_stack_test.cpp).
#include <gtest/gtest.h>

#include "player/haptic/haptic_cycle.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

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

TEST(HapticCycle, SumsKinaestheticAndVibrotactileAndLeavesTheClampToTheSafetyStack) {
  auto scene = scene_of({std::make_shared<ConstantForceShader>(Vec3{3.0, 0.0, 0.0})},
                        {std::make_shared<ConstantForceShader>(Vec3{-1.0, 4.0, 0.0})});
  HapticCycle cycle;
  cycle.set_scene(scene.get(), 0.0);
  const CycleOutput out = cycle.step(at({}), 0.0);
  EXPECT_EQ(out.parts.kinaesthetic_N, (Vec3{3.0, 0.0, 0.0}));
  EXPECT_EQ(out.parts.vibrotactile_N, (Vec3{-1.0, 4.0, 0.0}));
  EXPECT_EQ(out.total_N, (Vec3{2.0, 4.0, 0.0}));  // sqrt(20) N: the one clamp comes later
}

TEST(HapticCycle, NoSceneRendersZero) {
  HapticCycle cycle;
  EXPECT_EQ(cycle.step(at({0.01, 0, 0}), 0.0).total_N, Vec3{});
}

TEST(HapticCycle, SceneChangesCrossFadeThenRetireTheOldScene) {
  auto a = scene_of({std::make_shared<ConstantForceShader>(Vec3{1.0, 0.0, 0.0})});
  auto b = scene_of({std::make_shared<ConstantForceShader>(Vec3{0.0, 1.0, 0.0})});
  HapticCycle cycle({0.1});
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
