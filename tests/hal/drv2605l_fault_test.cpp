#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "hal/device_error.hpp"
#include "hal/device_service.hpp"
#include "hal/drv2605l_registers.hpp"
#include "hal/rest_on_exit.hpp"
#include "tests/hal/drv2605l_test_rig.hpp"

namespace vimg {
namespace {

using namespace drv2605l;
using test::Drv2605lRig;

std::vector<float> carrier(double duration_s, double amplitude = 0.8) {
  std::vector<float> samples(static_cast<std::size_t>(duration_s * 8000.0));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * 175.0 * static_cast<double>(i) / 8000.0));
  }
  return samples;
}

struct Player {
  Drv2605lDriver& driver;
  double time_s = 0.0;
  void play(const std::vector<float>& drive) {
    for (std::size_t start = 0; start < drive.size(); start += 80) {
      const std::size_t count = std::min<std::size_t>(80, drive.size() - start);
      driver.write(std::span<const float>(drive).subspan(start, count), time_s);
      time_s += static_cast<double>(count) / 8000.0;
    }
  }
};

std::vector<FaultEvent> drain(FaultLog& log) {
  std::vector<FaultEvent> events;
  while (auto event = log.pop()) events.push_back(*event);
  return events;
}

TEST(Drv2605lFaults, TransientErrorIsRetriedWithBackoffAndNotReported) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  player.play(carrier(0.02));
  const auto slept_before = rig.clock.total_slept_us();
  const auto writes_before = rig.chip.writes_to(kRtpInput).size();
  rig.bus.fail_next(2, EIO);
  player.play(carrier(0.02, 0.3));  // new level: RTP writes needed
  EXPECT_GT(rig.chip.writes_to(kRtpInput).size(), writes_before);
  EXPECT_EQ(rig.bus.failed_transfers(), 2);
  EXPECT_TRUE(drain(rig.driver->faults()).empty());
  // The backoff (100 + 200 us) was waited on the clock, on top of the pacing.
  EXPECT_GE(rig.clock.total_slept_us() - slept_before, 20'000 + 300 - 1000);
  EXPECT_FALSE(rig.driver->output_stopped());
}

TEST(Drv2605lFaults, PersistentNackIsReportedOnceAndPlaybackGoesOn) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  rig.bus.fail_next(4 * 5, EREMOTEIO);  // five updates' worth of attempts fail
  player.play(carrier(0.05));
  const auto events = drain(rig.driver->faults());
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FaultKind::transfer_failed);
  EXPECT_EQ(events[0].error_number, EREMOTEIO);
  const std::string message = describe(events[0], rig.driver->device_path());
  EXPECT_NE(message.find(rig.bus.path()), std::string::npos);
  EXPECT_FALSE(rig.driver->device_gone());
  EXPECT_GT(rig.chip.peek(kRtpInput), 0);  // later writes got through
}

TEST(Drv2605lFaults, DeviceGoneIsReportedAndTheServiceReconnectsItWhenItReturns) {
  Drv2605lRig rig;
  DeviceServiceOptions service_options;
  service_options.first_reconnect_interval_s = 0.1;
  DeviceService service(service_options);
  service.add(*rig.driver);
  auto service_time_ns = [&] { return rig.clock.now_us() * 1000; };  // one thread: the fake clock
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  player.play(carrier(0.05));
  rig.bus.set_unplugged(true);
  player.play(carrier(0.3, 0.5));  // rendering goes on while it is gone
  EXPECT_TRUE(rig.driver->device_gone());
  service.poll(service_time_ns());
  EXPECT_EQ(service.take_messages(),
            (std::vector<std::string>{describe({FaultKind::device_gone, ENODEV, 0}, rig.bus.path())}));
  rig.bus.set_unplugged(false);
  const int resets_before = rig.chip.resets();
  player.play(carrier(0.3, 0.5));
  EXPECT_TRUE(rig.driver->device_gone());  // the render thread does not reconnect
  EXPECT_EQ(rig.chip.resets(), resets_before);
  rig.clock.advance_us(100'000);
  service.poll(service_time_ns());
  EXPECT_FALSE(rig.driver->device_gone());
  EXPECT_EQ(service.take_messages(),
            (std::vector<std::string>{describe({FaultKind::reconnected, 0, 0}, rig.bus.path())}));
  EXPECT_EQ(rig.bus.reopen_count(), 1);
  EXPECT_EQ(rig.chip.resets(), resets_before + 1);  // initialized again
  EXPECT_EQ(rig.chip.peek(kMode) & 7u, kModeRtp);
  player.play(carrier(0.3, 0.5));  // output resumes
  EXPECT_NEAR(rig.chip.peek(kRtpInput), 128, 6);
  EXPECT_TRUE(rig.chip.violations().empty());
  EXPECT_TRUE(drain(rig.driver->faults()).empty());
}

TEST(Drv2605lFaults, OverCurrentStopsOutputAndSaysWhy) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  player.play(carrier(0.1));
  rig.chip.raise_status(kStatusOverCurrent);
  player.play(carrier(0.1));
  EXPECT_TRUE(rig.driver->output_stopped());
  EXPECT_TRUE(rig.chip.standby());
  EXPECT_EQ(rig.chip.peek(kRtpInput), 0);
  const auto events = drain(rig.driver->faults());
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FaultKind::over_current);
  EXPECT_NE(describe(events[0], "/dev/i2c-1").find("over-current"), std::string::npos);
  // No drive reaches the chip after the stop.
  const auto rtp_count = rig.chip.writes_to(kRtpInput).size();
  player.play(carrier(0.1));
  EXPECT_EQ(rig.chip.writes_to(kRtpInput).size(), rtp_count);
}

TEST(Drv2605lFaults, OverTemperatureStopsOutput) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  rig.chip.raise_status(kStatusOverTemp);
  player.play(carrier(0.1));
  EXPECT_TRUE(rig.driver->output_stopped());
  EXPECT_TRUE(rig.chip.standby());
  const auto events = drain(rig.driver->faults());
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FaultKind::over_temperature);
}

class RestTest : public ::testing::Test {
 protected:
  void SetUp() override { clear_rest_request(); }
  void TearDown() override { clear_rest_request(); }
};

TEST_F(RestTest, SigtermPutsTheActuatorToRestAtTheNextWrite) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  player.play(carrier(0.05));
  ASSERT_FALSE(rig.chip.standby());
  {
    SignalRestScope scope;
    ASSERT_EQ(std::raise(SIGTERM), 0);  // the handler only sets the flag: the process lives on
    EXPECT_EQ(rest_signal(), SIGTERM);
    const auto rtp_count = rig.chip.writes_to(kRtpInput).size();
    player.play(carrier(0.05));
    EXPECT_TRUE(rig.chip.standby());
    EXPECT_EQ(rig.chip.peek(kRtpInput), 0);
    EXPECT_EQ(rig.chip.writes_to(kRtpInput).size(), rtp_count + 1);  // only the zero
  }
  const auto events = drain(rig.driver->faults());
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, FaultKind::rest_requested);
}

TEST_F(RestTest, SigintToo) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  Player player{*rig.driver};
  player.play(carrier(0.05));
  SignalRestScope scope;
  ASSERT_EQ(std::raise(SIGINT), 0);
  player.play(carrier(0.01));
  EXPECT_TRUE(rig.chip.standby());
}

TEST_F(RestTest, AnExceptionPutsTheActuatorToRestThroughTheGuard) {
  Drv2605lRig rig;
  try {
    RestGuard guard(*rig.driver);
    rig.driver->open(8000.0);
    Player player{*rig.driver};
    player.play(carrier(0.05));
    ASSERT_FALSE(rig.chip.standby());
    throw std::runtime_error("renderer failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(rig.chip.standby());
  EXPECT_EQ(rig.chip.peek(kRtpInput), 0);
}

TEST_F(RestTest, NormalExitPutsTheActuatorToRestAndDropsEnable) {
  FakeClock clock(1'000'000);
  Drv2605lEmulator chip(clock);
  EmulatedI2cBus bus;
  bus.attach(0x5A, chip);
  {
    Drv2605lDriver driver(bus, &chip.enable_pin(), clock, test::lra_profile());
    driver.open(8000.0);
    Player player{driver};
    player.play(carrier(0.05));
    ASSERT_FALSE(chip.standby());
  }
  EXPECT_FALSE(chip.enabled());
  const auto& traffic = chip.traffic();
  ASSERT_GE(traffic.size(), 2u);
  EXPECT_EQ(traffic[traffic.size() - 2].reg, kRtpInput);
  EXPECT_EQ(traffic[traffic.size() - 2].value, 0);
  EXPECT_EQ(traffic.back().reg, kMode);
  EXPECT_EQ(traffic.back().value & kModeStandby, kModeStandby);
}

}  // namespace
}  // namespace vimg
