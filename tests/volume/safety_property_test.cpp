// The safety stack's promises over random scenes, devices and hands (seeded, deterministic):
// HapticCycle + SafetyStack (SafeHapticCycle) drive the simulated device with a simulated clock,
// cycle by cycle, while the hand wanders (out of the workspace too), the device stops measuring,
// cycles overrun, reads and writes fail and the run stops. On every cycle:
//   |F| <= clamp_N;
//   |F(n) - F(n-1)| <= max_slew * dt, except the one step to zero at a fault or a stop;
//   F = 0 on the very cycle a fault trips or the stop comes, and the device holds zero;
//   each fault trips exactly when its cause says (stale after the limit, overruns after K in a row).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/safe_haptic_cycle.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

constexpr double kDuration_s = 0.3;
constexpr double kTolerance_N = 1e-9;

struct Events {
  int freeze_from = -1, freeze_cycles = 0;    // the device stops measuring
  int overrun_from = -1, overrun_cycles = 0;  // previous_overran is set
  int fail_read_at = -1;
  int fail_write_at = -1;
  int stop_at = -1;
};

struct RandomCase {
  ForceDeviceLimits device;
  SafetySettings settings;
  double rate_hz = 1000.0;
  std::vector<HandPathPoint> hand;
  std::vector<std::shared_ptr<const ForceShader>> shaders;
  Events events;
};

RandomCase make_case(std::mt19937& rng) {
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto chance = [&](double p) { return uniform(0.0, 1.0) < p; };
  auto vec = [&](double r) { return Vec3{uniform(-r, r), uniform(-r, r), uniform(-r, r)}; };
  RandomCase c;
  c.device.max_force_N = uniform(0.5, 5.0);
  c.device.max_stiffness_N_per_m = uniform(100.0, 1000.0);
  c.device.workspace_m = {uniform(0.04, 0.2), uniform(0.04, 0.2), uniform(0.04, 0.2)};
  c.device.max_slew_N_per_ms = uniform(0.05, 3.0);
  c.settings.max_force_N = uniform(0.5, 5.0);
  c.settings.gate_force_N = chance(0.3) ? 1e9 : uniform(0.05, 1.0);
  c.settings.ramp_time_s = chance(0.3) ? 0.0 : uniform(0.0, 0.2);
  c.settings.wall_margin_m = uniform(0.0, 0.03);
  c.settings.wall_stiffness_N_per_m = uniform(0.0, 2000.0);
  c.settings.stale_limit_cycles = std::uniform_int_distribution<int>(2, 40)(rng);
  c.settings.overrun_limit_cycles = std::uniform_int_distribution<int>(1, 10)(rng);
  const double rates[] = {100.0, 250.0, 500.0, 1000.0, 2000.0, 4000.0};
  c.rate_hz = rates[std::uniform_int_distribution<int>(0, 5)(rng)];

  // A hand wandering through and out of the workspace.
  const int points = std::uniform_int_distribution<int>(2, 8)(rng);
  const Vec3 reach = 0.7 * c.device.workspace_m;
  for (int i = 0; i < points; ++i) {
    c.hand.push_back({kDuration_s * i / (points - 1),
                      Vec3{uniform(-reach.x, reach.x), uniform(-reach.y, reach.y), uniform(-reach.z, reach.z)}});
  }
  const int shaders = std::uniform_int_distribution<int>(1, 4)(rng);
  for (int i = 0; i < shaders; ++i) {
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
      case 0: c.shaders.push_back(std::make_shared<testing::ConstantForceShader>(vec(6.0))); break;
      case 1: c.shaders.push_back(std::make_shared<testing::AnchorSpringShader>(vec(0.05), uniform(50.0, 3000.0))); break;
      case 2: c.shaders.push_back(std::make_shared<testing::ActiveDamperShader>(uniform(0.0, 5.0))); break;
      case 3: c.shaders.push_back(std::make_shared<testing::StepShader>(vec(0.03), normalized(vec(1.0)), vec(4.0))); break;
      default: c.shaders.push_back(std::make_shared<testing::VibrationShader>(vec(2.0), uniform(20.0, 500.0))); break;
    }
  }
  const int cycles = static_cast<int>(kDuration_s * c.rate_hz);
  auto some_cycle = [&] { return std::uniform_int_distribution<int>(1, cycles - 1)(rng); };
  if (chance(0.3)) {
    c.events.freeze_from = some_cycle();
    c.events.freeze_cycles = std::uniform_int_distribution<int>(1, 60)(rng);
  }
  if (chance(0.3)) {
    c.events.overrun_from = some_cycle();
    c.events.overrun_cycles = std::uniform_int_distribution<int>(1, 12)(rng);
  }
  if (chance(0.1)) c.events.fail_read_at = some_cycle();
  if (chance(0.1)) c.events.fail_write_at = some_cycle();
  if (chance(0.3)) c.events.stop_at = some_cycle();
  return c;
}

bool in_window(int n, int from, int count) { return from >= 0 && n >= from && n < from + count; }

// The cycle at which the first fault must trip, or -1.
int expected_fault_cycle(const RandomCase& c) {
  int at = -1;
  auto earliest = [&](int n) {
    if (n >= 0 && (at < 0 || n < at)) at = n;
  };
  const Events& e = c.events;
  if (e.freeze_from >= 0 && e.freeze_cycles >= c.settings.stale_limit_cycles) {
    earliest(e.freeze_from + c.settings.stale_limit_cycles - 1);
  }
  if (e.overrun_from >= 0 && e.overrun_cycles >= c.settings.overrun_limit_cycles) {
    earliest(e.overrun_from + c.settings.overrun_limit_cycles - 1);
  }
  earliest(e.fail_read_at);
  earliest(e.fail_write_at);
  return at;
}

TEST(SafetyProperty, ClampSlewAndZeroAtFaultOrStopHoldOnEveryCycle) {
  std::mt19937 rng(20240611);
  int faults = 0, stops = 0, clamps = 0, slews = 0, walls = 0;
  for (int k = 0; k < 300; ++k) {
    SCOPED_TRACE("case " + std::to_string(k));
    const RandomCase c = make_case(rng);
    const double period_s = 1.0 / c.rate_hz;
    SimulatedForceDevice sim(c.hand, HandModel{}, c.device);
    HapticScene scene(DeviceProfile{}, {}, c.shaders, {});
    SafeHapticCycle cycle(c.device, c.settings, {0.05}, period_s);
    cycle.render().set_scene(&scene, 0.0);
    const double clamp = cycle.safety().clamp_N();
    ASSERT_LE(clamp, std::min(c.device.max_force_N, c.settings.max_force_N));
    const int fault_at = expected_fault_cycle(c);
    const int cycles = static_cast<int>(kDuration_s * c.rate_hz);

    Vec3 previous;
    double previous_s = -period_s;  // the device starts at rest
    for (int n = 0; n < cycles; ++n) {
      const double t = n * period_s;
      if (n == c.events.stop_at && (fault_at < 0 || n <= fault_at)) {
        const ForceCycleRecord r = cycle.stop(sim, t);
        EXPECT_EQ(r.force_N, Vec3{}) << n;
        EXPECT_EQ(r.flags, safety_flag::stop);
        EXPECT_EQ(sim.force_N(), Vec3{}) << n;
        ++stops;
        break;
      }
      sim.freeze_measurements(in_window(n, c.events.freeze_from, c.events.freeze_cycles));
      if (n == c.events.fail_read_at) sim.fail_next_read();
      if (n == c.events.fail_write_at) sim.fail_next_write();
      const bool overran = in_window(n, c.events.overrun_from, c.events.overrun_cycles);
      const ForceCycleRecord r = cycle.step(sim, t, overran);

      ASSERT_LE(norm(r.force_N), clamp + kTolerance_N) << n;
      // The device got what the record says (it clamps again to its own Fmax: rounding only).
      ASSERT_LE(norm(sim.force_N() - r.force_N), kTolerance_N) << n;
      clamps += (r.flags & safety_flag::clamp) != 0;
      slews += (r.flags & safety_flag::slew) != 0;
      walls += (r.flags & safety_flag::wall) != 0;
      if (r.fault != ForceFault::none) {
        EXPECT_EQ(n, fault_at);
        EXPECT_EQ(r.force_N, Vec3{}) << n;
        EXPECT_NE(r.flags & (safety_flag::stale | safety_flag::overrun | safety_flag::device), 0u);
        ++faults;
        break;
      }
      ASSERT_NE(n, fault_at) << "the fault did not trip";
      const double dt_ms = (t - previous_s) * 1e3;
      ASSERT_LE(norm(r.force_N - previous), c.device.max_slew_N_per_ms * dt_ms + kTolerance_N) << n;
      previous = r.force_N;
      previous_s = t;
    }
  }
  // The cases exercise every layer.
  EXPECT_GT(faults, 30);
  EXPECT_GT(stops, 30);
  EXPECT_GT(clamps, 1000);
  EXPECT_GT(slews, 1000);
  EXPECT_GT(walls, 1000);
}

}  // namespace
}  // namespace vimg
