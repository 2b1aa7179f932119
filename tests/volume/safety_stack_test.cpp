// The safety stack layer by layer, against its equations (player/haptic/safety_stack.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "player/haptic/safety_stack.hpp"

namespace vimg {
namespace {

constexpr double kPeriod_s = 1e-3;

ForceDeviceLimits device(double fmax = 3.3, double slew_N_per_ms = 1.0) {
  ForceDeviceLimits d;
  d.max_force_N = fmax;
  d.max_stiffness_N_per_m = 400.0;
  d.workspace_m = {0.16, 0.12, 0.10};
  d.max_slew_N_per_ms = slew_N_per_ms;
  return d;
}

// Every layer but the one under test out of the way: no gate, no wall in reach, a generous slew.
SafetySettings open_settings() {
  SafetySettings s;
  s.max_force_N = 100.0;
  s.gate_force_N = 1e9;
  s.ramp_time_s = 0.0;
  s.wall_margin_m = 0.0;
  s.stale_limit_cycles = 1000000;
  s.overrun_limit_cycles = 1000000;
  return s;
}

// Cycle n at n ms with a new probe position each time.
SafetyInput cycle(int n, Vec3 scene_N, Vec3 position_m = {}) {
  SafetyInput in;
  in.time_s = n * kPeriod_s;
  in.scene_N = scene_N;
  in.position_m = position_m;
  in.sequence = static_cast<std::uint64_t>(n);
  return in;
}

TEST(SafetyStackGate, HoldsTheSceneForceUntilItIsSmallThenRampsItInLinearly) {
  SafetySettings s = open_settings();
  s.gate_force_N = 0.2;
  s.ramp_time_s = 0.1;
  SafetyStack stack(s, device(3.3, 100.0), kPeriod_s);
  // A spring to the origin, 300 N/m, the probe 10 mm away moving in at 20 mm/s: 3 N at first.
  int released_at = -1;
  for (int n = 0; n <= 800; ++n) {
    const double x = std::max(0.0, 0.010 - 0.02 * n * kPeriod_s);
    const Vec3 scene{-300.0 * x, 0.0, 0.0};
    const SafetyOutput out = stack.apply(cycle(n, scene));
    if (released_at < 0 && norm(scene) < 0.2) released_at = n;
    if (released_at < 0) {
      EXPECT_EQ(out.force_N, Vec3{}) << n;
      EXPECT_TRUE(out.flags & safety_flag::gate) << n;
      continue;
    }
    const double ramp = std::min(1.0, (n - released_at) * kPeriod_s / 0.1);
    EXPECT_NEAR(out.force_N.x, ramp * scene.x, 1e-12) << n;
    EXPECT_EQ((out.flags & safety_flag::gate) != 0, ramp < 1.0) << n;
  }
  EXPECT_EQ(released_at, 467);  // |F| = 300 N/m (10 mm - 0.02 n mm) < 0.2 N from n = 467 on
}

TEST(SafetyStackGate, WithoutTheGateTheFirstCycleWouldStepToFullForce) {
  // The counterpart: the same start renders 3 N at once when the gate is open.
  SafetyStack stack(open_settings(), device(3.3, 100.0), kPeriod_s);
  EXPECT_NEAR(stack.apply(cycle(0, {-3.0, 0.0, 0.0})).force_N.x, -3.0, 1e-12);
}

TEST(SafetyStackWall, PushesBackInwardWithinTheMarginOnEachAxis) {
  SafetySettings s = open_settings();
  s.wall_margin_m = 0.010;
  s.wall_stiffness_N_per_m = 250.0;
  SafetyStack stack(s, device(3.3, 100.0), kPeriod_s);
  // Workspace 160 x 120 x 100 mm: inner faces at x = ±70, y = ±50, z = ±40 mm.
  EXPECT_EQ(stack.wall_force_N({0.069, -0.049, 0.039}), Vec3{});
  const Vec3 f = stack.wall_force_N({0.075, -0.052, 0.0});
  EXPECT_NEAR(f.x, -250.0 * 0.005, 1e-12);
  EXPECT_NEAR(f.y, 250.0 * 0.002, 1e-12);
  EXPECT_EQ(f.z, 0.0);
  // Beyond the workspace the spring goes on (the clamp bounds it).
  EXPECT_NEAR(stack.wall_force_N({0.0, 0.0, -0.060}).z, 250.0 * 0.020, 1e-12);

  const SafetyOutput inside = stack.apply(cycle(0, {0.1, 0.0, 0.0}, {0.0, 0.0, 0.0}));
  EXPECT_FALSE(inside.flags & safety_flag::wall);
  const SafetyOutput near_edge = stack.apply(cycle(1, {0.1, 0.0, 0.0}, {0.075, 0.0, 0.0}));
  EXPECT_TRUE(near_edge.flags & safety_flag::wall);
  EXPECT_NEAR(near_edge.force_N.x, 0.1 - 1.25, 1e-12);  // the scene's force plus the wall's
}

TEST(SafetyStackWall, StiffnessNeverExceedsTheDevicesKmax) {
  SafetySettings s = open_settings();
  s.wall_margin_m = 0.010;
  s.wall_stiffness_N_per_m = 5000.0;
  SafetyStack stack(s, device(), kPeriod_s);
  EXPECT_EQ(stack.wall_stiffness_N_per_m(), 400.0);
  EXPECT_NEAR(stack.wall_force_N({0.071, 0.0, 0.0}).x, -400.0 * 0.001, 1e-12);
}

TEST(SafetyStackClamp, ScalesTheForceToTheSmallerOfDeviceAndSceneLimits) {
  SafetySettings s = open_settings();
  s.max_force_N = 2.0;
  SafetyStack scene_limited(s, device(3.3, 100.0), kPeriod_s);
  EXPECT_EQ(scene_limited.clamp_N(), 2.0);
  const SafetyOutput out = scene_limited.apply(cycle(0, {3.0, 4.0, 0.0}));
  EXPECT_NEAR(norm(out.force_N), 2.0, 1e-12);
  EXPECT_NEAR(out.force_N.y / out.force_N.x, 4.0 / 3.0, 1e-12);  // same direction
  EXPECT_TRUE(out.flags & safety_flag::clamp);
  EXPECT_FALSE(scene_limited.apply(cycle(1, {1.0, 1.0, 0.0})).flags & safety_flag::clamp);

  SafetyStack device_limited(s, device(1.5, 100.0), kPeriod_s);
  EXPECT_EQ(device_limited.clamp_N(), 1.5);
  EXPECT_NEAR(norm(device_limited.apply(cycle(0, {0.0, 0.0, -9.0})).force_N), 1.5, 1e-12);
}

TEST(SafetyStackClamp, ANonFiniteForceBecomesZero) {
  SafetyStack stack(open_settings(), device(3.3, 100.0), kPeriod_s);
  // Before the gate opens a NaN keeps it closed (NaN is not below the gate force): zero.
  EXPECT_EQ(stack.apply(cycle(0, {std::nan(""), 0.0, 0.0})).force_N, Vec3{});
  ASSERT_EQ(stack.apply(cycle(1, {0.1, 0.0, 0.0})).force_N.x, 0.1);  // the gate opens
  const SafetyOutput out = stack.apply(cycle(2, {std::nan(""), 0.0, 0.0}));
  EXPECT_EQ(out.force_N, Vec3{});
  EXPECT_TRUE(out.flags & safety_flag::clamp);
  EXPECT_EQ(stack.apply(cycle(3, {INFINITY, 1.0, 0.0})).force_N, Vec3{});
}

TEST(SafetyStackSlew, LimitsTheChangePerCycleToSlewTimesDt) {
  SafetyStack stack(open_settings(), device(3.3, 1.0), kPeriod_s);
  // 0 -> 3 N at 1 N/ms, 1 ms cycles: 1, 2, 3 N (the first cycle starts from rest).
  for (int n = 0; n < 3; ++n) {
    const SafetyOutput out = stack.apply(cycle(n, {0.0, 3.0, 0.0}));
    EXPECT_NEAR(out.force_N.y, n + 1.0, 1e-12) << n;
    EXPECT_EQ((out.flags & safety_flag::slew) != 0, n < 2) << n;
  }
  // Down to -3 N along x in 0.25 ms cycles: each step at most 0.25 N, along the change.
  Vec3 last = stack.last_force_N();
  for (int n = 0; n < 40; ++n) {
    SafetyInput in = cycle(0, {-3.0, 0.0, 0.0});
    in.time_s = 2e-3 + (n + 1) * 0.25e-3;
    in.sequence = 100 + static_cast<std::uint64_t>(n);
    const Vec3 f = stack.apply(in).force_N;
    EXPECT_LE(norm(f - last), 0.25 + 1e-12) << n;
    last = f;
  }
  EXPECT_NEAR(last.x, -3.0, 1e-12);
  EXPECT_NEAR(last.y, 0.0, 1e-12);
}

TEST(SafetyStackSlew, TheLimitComesFromTheDevice) {
  SafetyStack slow(open_settings(), device(3.3, 0.2), kPeriod_s);
  EXPECT_NEAR(slow.apply(cycle(0, {1.0, 0.0, 0.0})).force_N.x, 0.2, 1e-12);
  ForceDeviceLimits unknown = device();
  unknown.max_slew_N_per_ms = 0.0;  // no figure: the default
  EXPECT_EQ(SafetyStack(open_settings(), unknown, kPeriod_s).max_slew_N_per_ms(), kDefaultMaxSlew_N_per_ms);
}

TEST(SafetyStackStale, NoNewPositionForTheLimitZeroesTheForceAndFaults) {
  SafetySettings s = open_settings();
  s.stale_limit_cycles = 20;
  SafetyStack stack(s, device(3.3, 100.0), kPeriod_s);
  const Vec3 scene{0.5, 0.0, 0.0};
  for (int n = 0; n < 10; ++n) ASSERT_EQ(stack.apply(cycle(n, scene)).force_N, scene);
  // 19 cycles with the sequence of cycle 9, then a new position: no fault.
  for (int n = 10; n < 29; ++n) {
    SafetyInput in = cycle(n, scene);
    in.sequence = 9;
    ASSERT_EQ(stack.apply(in).fault, ForceFault::none) << n;
  }
  EXPECT_EQ(stack.apply(cycle(29, scene)).force_N, scene);
  // 20 unchanged: the 20th zeroes the force.
  for (int n = 30; n < 50; ++n) {
    SafetyInput in = cycle(n, scene);
    in.sequence = 29;
    const SafetyOutput out = stack.apply(in);
    if (n < 49) {
      EXPECT_EQ(out.force_N, scene) << n;
    } else {
      EXPECT_EQ(out.force_N, Vec3{});
      EXPECT_EQ(out.fault, ForceFault::stale_input);
      EXPECT_TRUE(out.flags & safety_flag::stale);
    }
  }
  // Latched: new positions do not bring the force back.
  const SafetyOutput after = stack.apply(cycle(50, scene));
  EXPECT_EQ(after.force_N, Vec3{});
  EXPECT_EQ(after.fault, ForceFault::stale_input);
  stack.reset();
  EXPECT_EQ(stack.fault(), ForceFault::none);
  EXPECT_EQ(stack.apply(cycle(51, scene)).force_N, scene);
}

TEST(SafetyStackOverrun, TheLimitOfOverrunsInARowZeroesTheForceAndFaults) {
  SafetySettings s = open_settings();
  s.overrun_limit_cycles = 5;
  SafetyStack stack(s, device(3.3, 100.0), kPeriod_s);
  const Vec3 scene{0.0, 0.0, -0.4};
  int n = 0;
  // Four in a row, then an on-time cycle: the count starts again.
  for (int k = 0; k < 4; ++k, ++n) {
    SafetyInput in = cycle(n, scene);
    in.previous_overran = true;
    ASSERT_EQ(stack.apply(in).force_N, scene) << n;
  }
  ASSERT_EQ(stack.apply(cycle(n++, scene)).force_N, scene);
  for (int k = 0; k < 5; ++k, ++n) {
    SafetyInput in = cycle(n, scene);
    in.previous_overran = true;
    const SafetyOutput out = stack.apply(in);
    EXPECT_EQ(out.force_N == Vec3{}, k == 4) << k;
    EXPECT_EQ(out.fault == ForceFault::overruns, k == 4) << k;
    EXPECT_EQ((out.flags & safety_flag::overrun) != 0, k == 4) << k;
  }
}

TEST(SafetyStack, StopAndDeviceFaultsSendZeroAtOnceEvenAgainstTheSlewLimit) {
  SafetyStack stack(open_settings(), device(3.3, 0.5), kPeriod_s);
  for (int n = 0; n < 10; ++n) stack.apply(cycle(n, {3.0, 0.0, 0.0}));
  ASSERT_NEAR(stack.last_force_N().x, 3.0, 1e-12);
  const SafetyOutput stopped = stack.stop();
  EXPECT_EQ(stopped.force_N, Vec3{});
  EXPECT_EQ(stopped.flags, safety_flag::stop);
  EXPECT_EQ(stack.last_force_N(), Vec3{});
  // After a stop the next force ramps up from zero again under the slew limit.
  EXPECT_NEAR(stack.apply(cycle(10, {3.0, 0.0, 0.0})).force_N.x, 0.5, 1e-12);

  const SafetyOutput failed = stack.device_fault(ForceFault::device_write);
  EXPECT_EQ(failed.force_N, Vec3{});
  EXPECT_EQ(failed.flags, safety_flag::device);
  EXPECT_EQ(failed.fault, ForceFault::device_write);
  EXPECT_EQ(stack.apply(cycle(11, {3.0, 0.0, 0.0})).force_N, Vec3{});  // latched
}

TEST(SafetyStack, FlagNamesInLayerOrder) {
  EXPECT_EQ(safety_flag_names(0), "");
  EXPECT_EQ(safety_flag_names(safety_flag::slew | safety_flag::gate | safety_flag::clamp), "gate|clamp|slew");
  EXPECT_EQ(safety_flag_names(safety_flag::stop), "stop");
  EXPECT_EQ(safety_flag_names(0xFF), "gate|wall|clamp|slew|stale|overrun|device|stop");
}

}  // namespace
}  // namespace vimg
