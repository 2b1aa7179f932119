// The threaded haptic loop under the default watchdog limits (10 overruns in a row at 1 kHz) when
// short stalls come close together, as at the start of a loop on a machine busy elsewhere: the
// device blocks for 2 periods in the reads of cycles 1, 3, 5, 7, 9 and 11. The loop is never more
// than about two periods behind and catches up after each stall; the cycles between the stalls
// take microseconds. Before the watchdog counted only work that does not fit in the period, every
// cycle finished after its next deadline and counted as an overrun: ten in a row at cycle 10 and
// the fault (seen red that way). The stalls are sleeps of at least their length, so a slower
// machine only adds to them (unless it stalls the loop by 3 more periods, when the loop skips). The catch-up rule itself is tested on a simulated clock
// in tests/realtime/catch_up_test.cpp.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "player/haptic/haptic_loop.hpp"
#include "primitives/shader.hpp"
#include "realtime/clock.hpp"

namespace vimg {
namespace {

// A device that measures a probe at rest on every read; the odd reads up to the 11th block for
// `stall_ns` first.
class CloseStallsPort final : public HapticPort {
 public:
  explicit CloseStallsPort(std::int64_t stall_ns) : stall_ns_(stall_ns) {}
  bool read(double, ProbeSample& sample) override {
    ++reads_;
    if (reads_ <= 11 && reads_ % 2 == 1) {
      sleep_until_ns(monotonic_ns() + stall_ns_);
      stalls_.fetch_add(1, std::memory_order_release);
    }
    sample = ProbeSample{};
    sample.sequence = reads_;
    return true;
  }
  bool write_force(const Vec3& force_N) override {
    last_N_ = force_N;
    return true;
  }
  ForceDeviceLimits limits() const override { return {}; }
  int stalls() const { return stalls_.load(std::memory_order_acquire); }
  const Vec3& last_N() const { return last_N_; }  // after the loop stopped

 private:
  std::int64_t stall_ns_;
  std::uint64_t reads_ = 0;  // loop thread
  std::atomic<int> stalls_{0};
  Vec3 last_N_;
};

class SmallForce final : public ForceShader {
 public:
  void begin_contact(ShaderState&) const override {}
  Vec3 force_N(const InteractionState&, ShaderState&) const override { return {0.1, 0.0, 0.0}; }
  bool active(const ShaderState&) const override { return true; }
};

TEST(HapticLoopCloseStalls, StallsOfTwoPeriodsAtEveryOtherCycleOfTheStartDoNotFaultTheLoop) {
  HapticLoopConfig config;  // 1 kHz, the default safety settings
  ASSERT_EQ(config.safety.overrun_limit_cycles, 10);
  const auto period_ns = static_cast<std::int64_t>(1e9 / config.rate_hz);
  CloseStallsPort port(period_ns * 2);
  HapticLoop loop(port, config);
  loop.submit_scene(std::make_unique<HapticScene>(DeviceProfile{}, std::vector<std::shared_ptr<const void>>{},
                                                  std::vector<std::shared_ptr<const ForceShader>>{std::make_shared<SmallForce>()},
                                                  std::vector<std::shared_ptr<const ForceShader>>{}));
  ASSERT_TRUE(loop.start());
  // A state, not a time: all six stalls done and 50 cycles after them, or the loop stopped.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (loop.running() && !(port.stalls() == 6 && loop.cycles() >= 60) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(port.stalls(), 6);
  EXPECT_TRUE(loop.running()) << loop.fault_text();
  EXPECT_EQ(loop.fault(), ForceFault::none) << loop.fault_text();
  // The telemetry still shows that the loop was behind its schedule after each stall.
  EXPECT_GE(loop.timing().overruns, 6u);
  loop.stop();
  EXPECT_EQ(loop.state(), LoopState::stopped);
  EXPECT_EQ(port.last_N(), Vec3{});
}

// Work that does not fit in the period still trips the watchdog, on the very cycle the limit is
// reached: every read blocks for 1.5 periods.
class SlowPort final : public HapticPort {
 public:
  explicit SlowPort(std::int64_t work_ns) : work_ns_(work_ns) {}
  bool read(double, ProbeSample& sample) override {
    sleep_until_ns(monotonic_ns() + work_ns_);
    sample = ProbeSample{};
    sample.sequence = ++reads_;
    return true;
  }
  bool write_force(const Vec3&) override { return true; }
  ForceDeviceLimits limits() const override { return {}; }

 private:
  std::int64_t work_ns_;
  std::uint64_t reads_ = 0;
};

TEST(HapticLoopCloseStalls, WorkThatDoesNotFitInThePeriodStillFaults) {
  HapticLoopConfig config;
  const auto period_ns = static_cast<std::int64_t>(1e9 / config.rate_hz);
  SlowPort port(period_ns * 3 / 2);
  HapticLoop loop(port, config);
  ASSERT_TRUE(loop.start());
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (loop.running() && std::chrono::steady_clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(loop.state(), LoopState::faulted);
  EXPECT_EQ(loop.fault(), ForceFault::overruns) << loop.fault_text();
  EXPECT_EQ(loop.cycles(), static_cast<std::uint64_t>(config.safety.overrun_limit_cycles) + 1);  // 10 slow, then the fault
}

}  // namespace
}  // namespace vimg
