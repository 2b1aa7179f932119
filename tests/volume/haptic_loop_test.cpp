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

std::unique_ptr<HapticScene> constant_scene(const Vec3& f) {
  return std::make_unique<HapticScene>(DeviceProfile{}, std::vector<std::shared_ptr<const void>>{},
                                       std::vector<std::shared_ptr<const ForceShader>>{std::make_shared<ConstantForceShader>(f)},
                                       std::vector<std::shared_ptr<const ForceShader>>{});
}

// A device wrapper that records every force it is sent, for the threaded tests.
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
  double max_force_N() const override { return inner_.max_force_N(); }
  std::vector<Vec3> forces_;
  std::vector<double> times_;  // loop time of the cycle that sent each force

 private:
  double last_read_s_ = 0.0;
  SimulatedForceDevice& inner_;
};

void wait_for_cycles(const HapticLoop& loop, std::uint64_t n) {
  for (int i = 0; i < 5000 && loop.cycles() < n; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

TEST(HapticLoop, RunsRendersAndZeroesTheForceOnStop) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  RecordingDevice device(sim);
  HapticLoop loop(device, {1000.0, {3.3, 0.2, 0.05, 0.05}});
  loop.submit_scene(constant_scene({0.0, 0.0, 0.15}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 200);
  EXPECT_GE(loop.cycles(), 200u);
  EXPECT_NEAR(loop.last_sent_N().z, 0.15, 1e-12);  // ramped in fully after 50 ms
  loop.stop();
  ASSERT_FALSE(device.forces_.empty());
  EXPECT_EQ(device.forces_.back(), Vec3{});
  EXPECT_EQ(sim.force_N(), Vec3{});
  const JitterStats j = loop.jitter();
  EXPECT_EQ(j.cycles, loop.cycles() + (loop.failed() ? 1 : 0));
  EXPECT_LE(j.p50_us, j.p99_us);
  EXPECT_LE(j.p99_us, j.max_us + 1.0);
}

TEST(HapticLoop, ADeviceErrorStopsTheLoopWithZeroForce) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  RecordingDevice device(sim);
  HapticLoop loop(device, {1000.0, {3.3, 0.2, 0.0, 0.05}});
  loop.submit_scene(constant_scene({0.1, 0.0, 0.0}));
  ASSERT_TRUE(loop.start());
  wait_for_cycles(loop, 20);
  sim.fail_next_read();
  for (int i = 0; i < 2000 && loop.running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_FALSE(loop.running());
  EXPECT_TRUE(loop.failed());
  EXPECT_EQ(device.forces_.back(), Vec3{});
  loop.stop();
}

TEST(HapticLoop, SceneSwapsWhileRunningCrossFade) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  RecordingDevice device(sim);
  HapticLoop loop(device, {1000.0, {3.3, 0.2, 0.0, 0.05}});
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
    HapticLoop loop(sim, {1000.0, {3.3, 0.2, 0.0, 10.0}});  // a 10 s cross-fade
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

TEST(HapticLoop, RejectsRatesOutside100To4000Hz) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  HapticLoop fast(sim, {8000.0, {}});
  EXPECT_FALSE(fast.start());
  HapticLoop ok(sim, {4000.0, {}});
  EXPECT_TRUE(ok.start());
  ok.stop();
}

}  // namespace
}  // namespace vimg
