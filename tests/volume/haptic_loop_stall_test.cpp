// The threaded loop under the default watchdog limits: a device that blocks once for 10.5
// periods (a stall of the machine or of the bus) does not fault the loop. The catch-up rule
// itself is tested on a simulated clock in tests/realtime/catch_up_test.cpp.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/haptic_loop.hpp"
#include "realtime/clock.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

// The simulated device; its write number `stall_at` blocks for `stall_ns` before it returns.
class StallingDevice final : public HapticPort {
 public:
  StallingDevice(SimulatedForceDevice& inner, int stall_at, std::int64_t stall_ns)
      : inner_(inner), stall_at_(stall_at), stall_ns_(stall_ns) {}
  bool read(double t, ProbeSample& s) override { return inner_.read(t, s); }
  bool write_force(const Vec3& f) override {
    const bool ok = inner_.write_force(f);
    if (++writes_ == stall_at_) {
      const std::int64_t from_ns = monotonic_ns();
      sleep_until_ns(from_ns + stall_ns_);
      stalled_ns_.store(monotonic_ns() - from_ns, std::memory_order_relaxed);
      stall_done_.store(true, std::memory_order_release);
    }
    return ok;
  }
  ForceDeviceLimits limits() const override { return inner_.limits(); }
  bool stall_done() const { return stall_done_.load(std::memory_order_acquire); }
  std::int64_t stalled_ns() const { return stalled_ns_.load(std::memory_order_relaxed); }

 private:
  SimulatedForceDevice& inner_;
  int stall_at_;
  std::int64_t stall_ns_;
  int writes_ = 0;  // loop thread only
  std::atomic<bool> stall_done_{false};
  std::atomic<std::int64_t> stalled_ns_{0};
};

// Polls the loop's state (never a fixed sleep): until `done` holds or the loop stops.
template <class Done>
void wait_while_running(const HapticLoop& loop, Done done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (loop.running() && !done() && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

TEST(HapticLoopStall, OneStallOfTenAndAHalfPeriodsUnderTheDefaultLimitsDoesNotFault) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{HandPathPoint{0.0, Vec3{}}});
  HapticLoopConfig config;  // 1 kHz, the default safety settings: 10 overruns, 20 stale cycles
  ASSERT_EQ(config.safety.overrun_limit_cycles, 10);
  const auto period_ns = static_cast<std::int64_t>(1e9 / config.rate_hz);
  StallingDevice device(sim, 100, period_ns * 21 / 2);
  HapticLoop loop(device, config);
  loop.submit_scene(std::make_unique<HapticScene>(
      DeviceProfile{}, std::vector<std::shared_ptr<const void>>{},
      std::vector<std::shared_ptr<const ForceShader>>{std::make_shared<testing::ConstantForceShader>(Vec3{0.1, 0.0, 0.0})},
      std::vector<std::shared_ptr<const ForceShader>>{}));
  ASSERT_TRUE(loop.start());
  std::uint64_t after_stall = 0;
  wait_while_running(loop, [&] {
    if (after_stall == 0 && device.stall_done()) after_stall = loop.cycles();
    return after_stall != 0 && loop.cycles() >= after_stall + 50;
  });
  const LoopTimingStats timing = loop.timing();
  ASSERT_TRUE(device.stall_done());
  EXPECT_GE(device.stalled_ns(), period_ns * 21 / 2);
  EXPECT_TRUE(loop.running()) << loop.fault_text();
  EXPECT_EQ(loop.fault(), ForceFault::none) << loop.fault_text();
  EXPECT_GE(timing.overruns, 1u);  // the stalled cycle itself
  loop.stop();
  EXPECT_EQ(loop.state(), LoopState::stopped);
  EXPECT_EQ(sim.force_N(), Vec3{});
}

}  // namespace
}  // namespace vimg
