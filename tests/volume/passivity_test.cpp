// The coupled system (simulated device and hand, the loop's whole cycle at 1 kHz: render and
// safety stack, kinaesthetic scene) must not gain energy: the work the rendered force does on the probe, W = integral F . dx, never
// exceeds a small tolerance over 10 s of pushing into, along and out of the data.
#include <gtest/gtest.h>

#include <cmath>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/safe_haptic_cycle.hpp"
#include "primitives/kinaesthetic/vector_guidance.hpp"
#include "primitives/kinaesthetic/yielding_surface.hpp"
#include "tests/volume/analytic_fields.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

// A hand that pushes 8 mm into z < 0 and back, sideways too, for 10 s.
std::vector<HandPathPoint> pushing_path() {
  std::vector<HandPathPoint> path;
  for (int i = 0; i <= 10000; ++i) {
    const double t = i * 1e-3;
    path.push_back({t, Vec3{0.02 * std::sin(2.0 * t), 0.01 * std::sin(3.1 * t), -0.004 + 0.006 * std::sin(5.3 * t)}});
  }
  return path;
}

struct EnergyRun {
  double max_work_J = -1e9;
  double final_work_J = 0.0;
};

EnergyRun run(std::shared_ptr<const ForceShader> shader) {
  SimulatedForceDevice device(pushing_path());
  HapticScene scene(DeviceProfile{}, {}, {std::move(shader)}, {});
  SafetySettings safety;
  safety.gate_force_N = 1e9;  // no start-up gate: the scene's force from the first cycle
  safety.ramp_time_s = 0.0;
  SafeHapticCycle cycle(device.limits(), safety, {0.1}, 1e-3);
  cycle.render().set_scene(&scene, 0.0);
  EnergyRun r;
  for (int i = 0; i <= 10000; ++i) {
    const double t = i * 1e-3;
    EXPECT_EQ(cycle.step(device, t, false).fault, ForceFault::none);
    r.max_work_J = std::max(r.max_work_J, device.environment_work_J());
  }
  r.final_work_J = device.environment_work_J();
  return r;
}

constexpr double kToleranceJ = 1e-4;

TEST(Passivity, YieldingSurfaceGainsNoEnergyOver10s) {
  static const testing::LinearScalar field({0.0, 0.0, 1000.0}, 0.0);
  const EnergyRun r = run(std::make_shared<YieldingSurfaceShader>(field, YieldingSurfaceParams{{400.0, 0.5}, 2.0, 0.4, 1.0}));
  EXPECT_LE(r.max_work_J, kToleranceJ);
  EXPECT_LT(r.final_work_J, 0.0);  // friction and yielding dissipate
}

TEST(Passivity, VectorGuidanceGainsNoEnergyOver10s) {
  static const testing::UniformVector field(normalized(Vec3{1.0, 0.0, 1.0}));
  const EnergyRun r = run(std::make_shared<VectorGuidanceShader>(field, VectorGuidanceParams{{400.0, 0.5}, 1.5, 0.0, 1e-6}));
  EXPECT_LE(r.max_work_J, kToleranceJ);
}

TEST(Passivity, TheCheckCatchesAnActiveEnvironment) {
  // Negative damping feeds energy in: the same measure must see it.
  const EnergyRun r = run(std::make_shared<testing::ActiveDamperShader>(0.5));
  EXPECT_GT(r.max_work_J, 10.0 * kToleranceJ);
}

}  // namespace
}  // namespace vimg
