// Restarting the threaded loop: start() re-arms the safety stack (the gate closed again, no fault),
// after a stop and after a fault. Every cycle of the second run is checked in the loop's log.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/haptic_loop.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

std::unique_ptr<HapticScene> constant_scene(const Vec3& f) {
  return std::make_unique<HapticScene>(
      DeviceProfile{}, std::vector<std::shared_ptr<const void>>{},
      std::vector<std::shared_ptr<const ForceShader>>{std::make_shared<testing::ConstantForceShader>(f)},
      std::vector<std::shared_ptr<const ForceShader>>{});
}

// Gate at 0.2 N, no ramp, no cross-fade (a new scene is the whole force at once), a log.
HapticLoopConfig restart_config() {
  HapticLoopConfig c;
  c.crossfade_time_s = 0.0;
  c.safety.gate_force_N = 0.2;
  c.safety.ramp_time_s = 0.0;
  c.safety.overrun_limit_cycles = 1000000;  // a loaded machine may stall the thread
  c.log_capacity_rows = 8192;
  return c;
}

// Polls the loop's state (never a fixed sleep) until `done` or the loop leaves `running`.
template <class Done>
void wait_while_running(const HapticLoop& loop, Done done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (loop.running() && !done() && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

std::vector<ForceCycleRecord> take_all(HapticLoop& loop) {
  std::vector<ForceCycleRecord> rows(8192);
  rows.resize(loop.take_log_rows(rows));
  return rows;
}

// The second run holds a 0.5 N scene, above the gate: every cycle but the stop's sends exactly
// zero with the gate flag, which holds only if start() closed the gate again.
void expect_gated_second_run(HapticLoop& loop, double first_run_end_s) {
  loop.submit_scene(constant_scene({0.5, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  EXPECT_EQ(loop.fault(), ForceFault::none);
  wait_while_running(loop, [&] { return loop.cycles() >= 40; });
  EXPECT_TRUE(loop.running()) << loop.fault_text();
  loop.stop();
  const std::vector<ForceCycleRecord> rows = take_all(loop);
  ASSERT_GE(rows.size(), 41u);
  ASSERT_EQ(rows.size(), loop.cycles());
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    ASSERT_EQ(rows[i].force_N, Vec3{}) << i;
    ASSERT_EQ(rows[i].flags, safety_flag::gate) << i;
    ASSERT_EQ(rows[i].fault, ForceFault::none) << i;
  }
  EXPECT_EQ(rows.back().flags, safety_flag::stop);
  // The loop's time goes on from the first run (the simulated device measures again only when its
  // time advances: a loop time that went back to zero looked like stale input).
  EXPECT_GT(rows.front().time_s, first_run_end_s);
}

TEST(HapticLoopRestart, AfterAStopTheGateIsClosedAgain) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  HapticLoop loop(sim, restart_config());
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));  // below the gate: it opens at once
  ASSERT_TRUE(loop.start());
  wait_while_running(loop, [&] { return loop.cycles() >= 100; });
  ASSERT_TRUE(loop.running());
  EXPECT_EQ(loop.last_sent_N(), (Vec3{0.1, 0.0, 0.0}));
  EXPECT_EQ(loop.last_flags(), 0u);  // the gate is open
  loop.stop();
  const std::vector<ForceCycleRecord> first = take_all(loop);
  ASSERT_EQ(first.size(), loop.cycles());
  expect_gated_second_run(loop, first.back().time_s);
}

TEST(HapticLoopRestart, AfterAStaleInputFaultTheLoopRunsAgainGated) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  HapticLoopConfig c = restart_config();
  c.safety.stale_limit_cycles = 20;
  HapticLoop loop(sim, c);
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  wait_while_running(loop, [&] { return loop.cycles() >= 30; });
  ASSERT_EQ(loop.last_sent_N(), (Vec3{0.1, 0.0, 0.0}));
  sim.freeze_measurements(true);
  wait_while_running(loop, [] { return false; });
  ASSERT_EQ(loop.state(), LoopState::faulted);
  ASSERT_EQ(loop.fault(), ForceFault::stale_input);
  loop.stop();
  const std::vector<ForceCycleRecord> first = take_all(loop);
  ASSERT_FALSE(first.empty());
  sim.freeze_measurements(false);
  expect_gated_second_run(loop, first.back().time_s);
  EXPECT_EQ(loop.state(), LoopState::stopped);
  EXPECT_EQ(loop.fault_text(), "");
}

}  // namespace
}  // namespace vimg
