// One location-study trial in process: the real haptic loop (its thread, the whole safety stack) on
// the simulated device through the port that takes the mark, watched as vimg-force watches it
// (apps/force/loop_run.hpp). The mark is the hand's place on its path at the scripted press, on the
// loop's own clock; the device is at rest (zero force) when the watch returns, whether the trial was
// marked or a signal came.
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <thread>

#include "apps/force/location_study_port.hpp"
#include "apps/force/location_study_trial.hpp"
#include "apps/force/loop_run.hpp"
#include "hal/force/force_device_opener.hpp"

namespace vimg::force_app {
namespace {

// A hand crossing the workspace diagonally in x-z (across the flow, which pushes back), through the
// feature plane at 0.6 s.
std::vector<HandPathPoint> crossing_hand(const StudyLayout& layout) {
  const double z = layout.plane_z_mm * 1e-3;
  return {{0.0, {-0.06, 0.0, z - 0.02}}, {1.2, {0.06, 0.0, z + 0.02}}};
}

HapticLoopConfig loop_config() {
  HapticLoopConfig config = haptic_loop_config(location_study_device(), 0);
  config.log_capacity_rows = 4000;
  return config;
}

// The largest |F| the device got, and the last force, from the loop's log.
struct LoggedForces {
  double largest_N = 0.0;
  Vec3 last_N{1.0, 1.0, 1.0};
  std::uint32_t last_flags = 0;
  std::size_t rows = 0;
};

LoggedForces drain(HapticLoop& loop) {
  LoggedForces f;
  std::vector<ForceCycleRecord> rows(4096);
  for (std::size_t n; (n = loop.take_log_rows(rows)) > 0;) {
    for (std::size_t i = 0; i < n; ++i) {
      f.largest_N = std::max(f.largest_N, norm(rows[i].force_N));
      f.last_N = rows[i].force_N;
      f.last_flags = rows[i].flags;
      ++f.rows;
    }
  }
  return f;
}

TEST(LocationStudyLoop, ATrialMarksTheHandAtTheScriptedTimeAndEndsAtRest) {
  const StudySet set = make_study_set(5);
  SimulatedForceDevice sim(crossing_hand(set.layout), HandModel{}, ForceDeviceLimits{});
  MarkingPort port(sim, 1000.0, 0.6005);
  HapticLoop loop(port, loop_config());
  loop.submit_scene(build_location_trial_scene(set, LocationMetaphor::transition_cue));
  ASSERT_TRUE(loop.start());
  std::atomic<int> no_signal{0};
  LoopWatch watch;
  watch.finished = [&] { return port.marked(); };
  const LoopRunEnd end = watch_loop(loop, no_signal, watch);
  EXPECT_EQ(end.why, LoopRunEnd::Why::finished) << end.fault;
  EXPECT_EQ(end.exit_code(), 0);
  ASSERT_TRUE(port.marked());
  const ProbeMark mark = port.mark();
  EXPECT_EQ(mark.time_s, 0.601);  // the first 1 ms cycle at or after the press
  EXPECT_EQ(mark.position_m, sim.hand_position_m(mark.time_s));
  EXPECT_NEAR(mark.position_m.x, -0.06 + 0.1 * 0.601, 1e-12);
  EXPECT_NEAR(mark.position_m.z, set.layout.plane_z_mm * 1e-3 - 0.02 + 0.04 * 0.601 / 1.2, 1e-12);
  // The scene was felt (guidance and the cue, after the gate's ramp), and the last force sent is zero.
  const LoggedForces f = drain(loop);
  EXPECT_GT(f.largest_N, 0.05);
  EXPECT_LE(f.largest_N, loop.safety().clamp_N() + 1e-12);
  EXPECT_GE(f.rows, 601u);
  EXPECT_EQ(f.last_N, Vec3{});
  EXPECT_EQ(f.last_flags, safety_flag::stop);
  EXPECT_EQ(sim.force_N(), Vec3{});
}

TEST(LocationStudyLoop, ASignalEndsTheTrialUnmarkedWithTheDeviceAtRest) {
  const StudySet set = make_study_set(6);
  SimulatedForceDevice sim(crossing_hand(set.layout), HandModel{}, ForceDeviceLimits{});
  MarkingPort port(sim, 1000.0, std::nullopt);
  HapticLoop loop(port, loop_config());
  loop.submit_scene(build_location_trial_scene(set, LocationMetaphor::roughness));
  ASSERT_TRUE(loop.start());
  std::atomic<int> signal{0};
  LoopWatch watch;
  watch.finished = [&] { return port.marked(); };
  // The signal comes once the ramp is over and the roughness is felt: a state, not a sleep.
  watch.tick = [&](double) {
    if (port.time_s() > 0.7) signal = SIGTERM;
  };
  const LoopRunEnd end = watch_loop(loop, signal, watch);
  EXPECT_EQ(end.why, LoopRunEnd::Why::signal);
  EXPECT_EQ(end.exit_code(), 143);
  EXPECT_EQ(end.reason("done"), "SIGTERM");
  EXPECT_FALSE(port.marked());
  const LoggedForces f = drain(loop);
  EXPECT_GT(f.largest_N, 0.05);
  EXPECT_EQ(f.last_N, Vec3{});
  EXPECT_EQ(f.last_flags, safety_flag::stop);
  EXPECT_EQ(sim.force_N(), Vec3{});
}

TEST(LocationStudyLoop, ADeviceFaultEndsTheTrialWithItsReason) {
  const StudySet set = make_study_set(7);
  SimulatedForceDevice sim(crossing_hand(set.layout), HandModel{}, ForceDeviceLimits{});
  MarkingPort port(sim, 1000.0, std::nullopt);
  HapticLoop loop(port, loop_config());
  loop.submit_scene(build_location_trial_scene(set, LocationMetaphor::roughness));
  ASSERT_TRUE(loop.start());
  std::atomic<int> no_signal{0};
  LoopWatch watch;
  watch.finished = [&] { return port.marked(); };
  bool failed = false;
  watch.tick = [&](double) {
    if (!failed && port.time_s() > 0.2) {
      failed = true;
      sim.fail_next_read();
    }
  };
  const LoopRunEnd end = watch_loop(loop, no_signal, watch);
  EXPECT_EQ(end.why, LoopRunEnd::Why::fault);
  EXPECT_EQ(end.exit_code(), 1);
  EXPECT_EQ(end.reason("done").rfind("device fault: device read failed", 0), 0u) << end.reason("done");
  EXPECT_EQ(sim.force_N(), Vec3{});
}

TEST(LocationStudyLoop, AFaultScriptedOnTheTrialClockEndsItThereUnmarkedAndAtRest) {
  // The simulated device's fault hook (what --sim-fault sets): the read at 0.1 s fails, on the
  // loop's cycle clock, however the wall clock runs; the press at 0.3 s never comes.
  const StudySet set = make_study_set(8);
  SimulatedForceDevice sim(crossing_hand(set.layout), HandModel{}, ForceDeviceLimits{});
  sim.fail_read_at(0.1);
  MarkingPort port(sim, 1000.0, 0.3);
  HapticLoop loop(port, loop_config());
  loop.submit_scene(build_location_trial_scene(set, LocationMetaphor::transition_cue));
  ASSERT_TRUE(loop.start());
  std::atomic<int> no_signal{0};
  LoopWatch watch;
  watch.finished = [&] { return port.marked(); };
  const LoopRunEnd end = watch_loop(loop, no_signal, watch);
  EXPECT_EQ(end.why, LoopRunEnd::Why::fault);
  EXPECT_EQ(end.reason("done").rfind("device fault: device read failed", 0), 0u) << end.reason("done");
  EXPECT_FALSE(port.marked());
  EXPECT_NEAR(port.time_s(), 0.099, 1e-12);  // the last read that went through: the cycle before 0.1 s
  const LoggedForces f = drain(loop);
  EXPECT_EQ(f.rows, 100u);  // 99 cycles and the fault's zero
  EXPECT_EQ(f.last_N, Vec3{});
  EXPECT_EQ(sim.force_N(), Vec3{});
}

}  // namespace
}  // namespace vimg::force_app
