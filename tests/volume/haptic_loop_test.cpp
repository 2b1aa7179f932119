// The threaded loop with the simulated device. Timing figures belong to bench/volume_bench.cpp;
// these tests check behaviour only.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/haptic_loop.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

using testing::ConstantForceShader;

std::unique_ptr<HapticScene> scene_of(std::vector<std::shared_ptr<const ForceShader>> shaders) {
  return std::make_unique<HapticScene>(DeviceProfile{}, std::vector<std::shared_ptr<const void>>{}, std::move(shaders),
                                       std::vector<std::shared_ptr<const ForceShader>>{});
}

std::unique_ptr<HapticScene> constant_scene(const Vec3& f) { return scene_of({std::make_shared<ConstantForceShader>(f)}); }

HapticLoopConfig config(double gate_N, double ramp_s, double crossfade_s) {
  HapticLoopConfig c;
  c.rate_hz = 1000.0;
  c.crossfade_time_s = crossfade_s;
  c.safety.gate_force_N = gate_N;
  c.safety.ramp_time_s = ramp_s;
  // A loaded test machine may stall the thread for a while: only the tests about the watchdogs
  // keep them tight.
  c.safety.stale_limit_cycles = 1000000;
  c.safety.overrun_limit_cycles = 1000000;
  return c;
}

ForceDeviceLimits fast_slew_limits() {
  ForceDeviceLimits limits;
  limits.max_slew_N_per_ms = 25.0;
  return limits;
}

// A device wrapper that records every force it is sent, with the loop time of the cycle.
class RecordingDevice final : public HapticPort {
 public:
  explicit RecordingDevice(SimulatedForceDevice& inner) : inner_(inner) {
    forces_.reserve(100000);
    times_.reserve(100000);
  }
  bool read(double t, ProbeSample& s) override {
    last_read_s_ = t;
    return inner_.read(t, s);
  }
  bool write_force(const Vec3& f) override {
    const bool ok = inner_.write_force(f);
    if (forces_.size() < forces_.capacity()) {
      forces_.push_back(f);
      times_.push_back(last_read_s_);
    }
    return ok;
  }
  ForceDeviceLimits limits() const override { return inner_.limits(); }
  std::vector<Vec3> forces_;
  std::vector<double> times_;  // loop time of the cycle that sent each force

 private:
  double last_read_s_ = 0.0;
  SimulatedForceDevice& inner_;
};

void wait_for_cycles(const HapticLoop& loop, std::uint64_t n) {
  for (int i = 0; i < 5000 && loop.cycles() < n && loop.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

void wait_until_stopped(const HapticLoop& loop) {
  for (int i = 0; i < 5000 && loop.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(HapticLoop, RunsRendersAndZeroesTheForceOnStop) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}}, HandModel{}, fast_slew_limits());
  RecordingDevice device(sim);
  HapticLoop loop(device, config(0.2, 0.05, 0.05));
  loop.submit_scene(constant_scene({0.0, 0.0, 0.15}));
  ASSERT_TRUE(loop.start());
  EXPECT_TRUE(loop.running());
  wait_for_cycles(loop, 200);
  EXPECT_GE(loop.cycles(), 200u);
  EXPECT_NEAR(loop.last_sent_N().z, 0.15, 1e-12);  // ramped in fully after 50 ms
  EXPECT_EQ(loop.last_flags(), 0u);
  loop.stop();
  EXPECT_EQ(loop.state(), LoopState::stopped);
  EXPECT_FALSE(loop.failed());
  ASSERT_FALSE(device.forces_.empty());
  EXPECT_EQ(device.forces_.back(), Vec3{});
  EXPECT_EQ(sim.force_N(), Vec3{});
  EXPECT_EQ(loop.last_sent_N(), Vec3{});
  EXPECT_EQ(loop.last_flags(), safety_flag::stop);
  EXPECT_NEAR(loop.max_sent_N(), 0.15, 1e-12);
  // Telemetry comes from LoopTelemetry: one wake per cycle, the stop cycle included.
  const LoopTimingStats t = loop.timing();
  EXPECT_EQ(t.cycles, loop.cycles());
  EXPECT_EQ(device.forces_.size(), loop.cycles());
  EXPECT_LE(t.jitter_p50_us, t.jitter_p99_us);
  EXPECT_LE(t.jitter_p99_us, t.jitter_max_us);
  EXPECT_GT(t.rate_hz, 0.0);
}

TEST(HapticLoop, ADeviceErrorStopsTheLoopWithZeroForceAndSaysWhy) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}}, HandModel{}, fast_slew_limits());
  RecordingDevice device(sim);
  HapticLoop loop(device, config(0.2, 0.0, 0.05));
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 20);
  sim.fail_next_read();
  wait_until_stopped(loop);
  EXPECT_FALSE(loop.running());
  EXPECT_TRUE(loop.failed());
  EXPECT_EQ(loop.fault(), ForceFault::device_read);
  EXPECT_EQ(loop.port_fault(), PortFault::io_error);
  EXPECT_EQ(loop.fault_text(), "device read failed: a transfer failed (device unplugged, no permission or a bus error)");
  EXPECT_EQ(device.forces_.back(), Vec3{});
  EXPECT_EQ(loop.last_flags(), safety_flag::device);
  loop.stop();
  EXPECT_EQ(loop.state(), LoopState::faulted);
}

TEST(HapticLoop, StaleInputFaultsWithZeroForce) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}}, HandModel{}, fast_slew_limits());
  RecordingDevice device(sim);
  HapticLoopConfig c = config(0.2, 0.0, 0.05);
  c.safety.stale_limit_cycles = 20;
  HapticLoop loop(device, c);
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 30);
  ASSERT_TRUE(loop.running());
  sim.freeze_measurements(true);
  wait_until_stopped(loop);
  EXPECT_EQ(loop.fault(), ForceFault::stale_input);
  EXPECT_EQ(loop.fault_text(), "stale input: the device sent no new probe position for 20 cycles");
  EXPECT_EQ(device.forces_.back(), Vec3{});
  EXPECT_EQ(sim.force_N(), Vec3{});
  EXPECT_TRUE(loop.last_flags() & safety_flag::stale);
}

TEST(HapticLoop, ClampAndSlewHoldOnEveryCycleOfTheThreadedLoop) {
  // A stiff spring far from the hand and a strong vibration: the scene asks for far more than
  // the device may render, and for steps far above its slew limit.
  std::vector<HandPathPoint> path;
  for (int i = 0; i <= 30; ++i) path.push_back({0.01 * i, Vec3{0.05 * std::sin(0.3 * i), 0.0, 0.0}});
  ForceDeviceLimits limits;
  limits.max_force_N = 2.0;
  limits.max_slew_N_per_ms = 0.5;
  SimulatedForceDevice sim(path, HandModel{}, limits);
  RecordingDevice device(sim);
  HapticLoopConfig c = config(1e9, 0.0, 0.05);
  c.safety.max_force_N = 3.0;
  c.log_capacity_rows = 4096;
  HapticLoop loop(device, c);
  loop.submit_scene(scene_of({std::make_shared<testing::AnchorSpringShader>(Vec3{0.02, 0.0, 0.0}, 3000.0),
                              std::make_shared<testing::VibrationShader>(Vec3{0.0, 1.5, 0.0}, 300.0)}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 300);
  loop.stop();
  ASSERT_GE(device.forces_.size(), 300u);
  EXPECT_EQ(loop.safety().clamp_N(), 2.0);
  Vec3 previous;
  double previous_s = -1e-3;
  for (std::size_t i = 0; i + 1 < device.forces_.size(); ++i) {
    const Vec3& f = device.forces_[i];
    ASSERT_LE(norm(f), 2.0 + 1e-9) << i;
    const double dt_ms = (device.times_[i] - previous_s) * 1e3;
    ASSERT_LE(norm(f - previous), 0.5 * dt_ms + 1e-9) << i;
    previous = f;
    previous_s = device.times_[i];
  }
  EXPECT_EQ(device.forces_.back(), Vec3{});
  EXPECT_GT(loop.clamp_hits(), 0u);

  // The log holds the same forces, one row per cycle, its last row the zero sent at stop.
  std::vector<ForceCycleRecord> rows(8192);
  const std::size_t n = loop.take_log_rows(rows);
  ASSERT_EQ(n + loop.log_rows_dropped(), loop.cycles());
  ASSERT_EQ(loop.log_rows_dropped(), 0u);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(rows[i].force_N, device.forces_[i]) << i;
  EXPECT_EQ(rows[n - 1].force_N, Vec3{});
  EXPECT_EQ(rows[n - 1].flags, safety_flag::stop);
  EXPECT_TRUE(rows[0].flags & safety_flag::slew);
}

TEST(HapticLoop, AFullLogRingDropsRowsButKeepsTheLastOne) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  HapticLoopConfig c = config(0.2, 0.0, 0.05);
  c.log_capacity_rows = 16;
  HapticLoop loop(sim, c);
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 100);
  loop.stop();
  std::vector<ForceCycleRecord> rows(64);
  const std::size_t n = loop.take_log_rows(rows);
  EXPECT_EQ(n, 16u);  // 15 ordinary rows and the last
  EXPECT_EQ(loop.log_rows_dropped(), loop.cycles() - 16);
  EXPECT_EQ(rows[n - 1].flags, safety_flag::stop);
  EXPECT_EQ(rows[n - 1].force_N, Vec3{});
}

TEST(HapticLoop, SceneSwapsWhileRunningCrossFade) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}}, HandModel{}, fast_slew_limits());
  RecordingDevice device(sim);
  HapticLoop loop(device, config(0.2, 0.0, 0.05));
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 50);
  for (int k = 0; k < 5; ++k) {
    loop.submit_scene(constant_scene({0.0, 0.1 * (k + 1), 0.0}));
    const auto at = loop.cycles();
    wait_for_cycles(loop, at + 120);
  }
  loop.stop();
  EXPECT_NEAR(device.forces_[device.forces_.size() - 2].y, 0.5, 1e-12);
  // Fading: each swap changes the force by at most 0.1 N * sqrt(2) (the first turns x into y),
  // spread over 50 ms, so between two cycles it moves by at most that times dt / 50 ms (dt is
  // larger when the loop was late and skipped ahead).
  for (std::size_t i = 1; i + 1 < device.forces_.size(); ++i) {
    const double dt = device.times_[i] - device.times_[i - 1];
    EXPECT_LE(norm(device.forces_[i] - device.forces_[i - 1]), 0.1 * std::sqrt(2.0) * dt / 0.05 + 1e-9) << i;
  }
}

// Destroying a running loop that holds a pending scene while a cross-fade is in progress: each
// scene must be deleted exactly once (ASan sees a double free or a use after free otherwise).
TEST(HapticLoop, DestroyedWhileRunningWithAPendingSceneDuringACrossFade) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  {
    HapticLoop loop(sim, config(0.2, 0.0, 10.0));  // a 10 s cross-fade
    loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
    ASSERT_TRUE(loop.start());
    wait_for_cycles(loop, 20);
    loop.submit_scene(constant_scene({0.0, 0.1, 0.0}));  // taken at once: the fade starts
    wait_for_cycles(loop, loop.cycles() + 20);
    loop.submit_scene(constant_scene({0.0, 0.0, 0.1}));  // waits: no scene is taken while fading
    ASSERT_TRUE(loop.running());
  }
  EXPECT_EQ(sim.force_N(), Vec3{});
}

// Restarts: haptic_loop_restart_test.cpp.

TEST(HapticLoop, RejectsRatesOutside100To4000Hz) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  HapticLoopConfig fast_config;
  fast_config.rate_hz = 8000.0;
  HapticLoop fast(sim, fast_config);
  EXPECT_FALSE(fast.start());
  HapticLoopConfig ok_config;
  ok_config.rate_hz = 4000.0;
  ok_config.safety.stale_limit_cycles = 1000000;
  ok_config.safety.overrun_limit_cycles = 1000000;
  HapticLoop ok(sim, ok_config);
  EXPECT_TRUE(ok.start());
  EXPECT_FALSE(ok.start());  // already running
  ok.stop();
}

}  // namespace
}  // namespace vimg
