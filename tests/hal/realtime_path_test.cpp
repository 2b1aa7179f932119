// The render thread's side of every hardware driver: write() never throws, never allocates or frees,
// and never reopens or initializes a device, whatever the bus does (transient errors, NACKs, the
// device going away and coming back). Reconnection is the device service's job (device_service_test).
#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "hal/bos1901_driver.hpp"
#include "hal/bos1901_emulator.hpp"
#include "hal/drv2605l_registers.hpp"
#include "hal/hid_haptic_controller.hpp"
#include "hal/hid_haptic_emulator.hpp"
#include "tests/hal/allocation_counter.hpp"
#include "tests/hal/drv2605l_test_rig.hpp"

namespace vimg {
namespace {

std::vector<float> carrier(double frequency_hz, double duration_s, double amplitude) {
  std::vector<float> samples(static_cast<std::size_t>(duration_s * 8000.0));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(amplitude *
                                    std::sin(2.0 * std::numbers::pi * frequency_hz * static_cast<double>(i) / 8000.0));
  }
  return samples;
}

// Plays drive in 80-sample blocks the way the renderer does, counting on this thread only what
// happens inside write(): allocations, frees and exceptions.
struct RenderThreadProbe {
  std::size_t allocations = 0;
  std::size_t frees = 0;
  int exceptions = 0;
  double time_s = 0.0;

  template <class Sink, class AfterBlock>
  void play(Sink& sink, const std::vector<float>& drive, AfterBlock&& after_block) {
    for (std::size_t start = 0; start < drive.size(); start += 80) {
      const std::size_t count = std::min<std::size_t>(80, drive.size() - start);
      const auto block = std::span<const float>(drive).subspan(start, count);
      {
        test::CountAllocations counted;
        try {
          sink.write(block, time_s);
        } catch (...) {
          ++exceptions;
        }
        allocations += counted.allocations();
        frees += counted.frees();
      }
      time_s += static_cast<double>(count) / 8000.0;
      after_block(count);
    }
  }
  template <class Sink>
  void play(Sink& sink, const std::vector<float>& drive) {
    play(sink, drive, [](std::size_t) {});
  }
};

std::vector<FaultKind> drain_kinds(FaultLog& log, std::vector<int>* error_numbers = nullptr) {
  std::vector<FaultKind> kinds;
  while (auto event = log.pop()) {
    kinds.push_back(event->kind);
    if (error_numbers != nullptr) error_numbers->push_back(event->error_number);
  }
  return kinds;
}

TEST(RealtimePath, Drv2605lWriteNeverThrowsAllocatesReopensOrInitializes) {
  test::Drv2605lRig rig;
  rig.driver->open(8000.0);
  rig.chip.reserve_traffic(100'000);
  const int throwing_before = rig.bus.throwing_transfers();
  const int resets_before = rig.chip.resets();
  RenderThreadProbe render;

  render.play(*rig.driver, carrier(175.0, 0.1, 0.8));  // closed loop at resonance
  render.play(*rig.driver, carrier(90.0, 0.1, 0.5));   // far from resonance: open loop, period writes
  rig.bus.fail_next(2, EIO);                            // transient: retried with backoff
  render.play(*rig.driver, carrier(175.0, 0.05, 0.3));
  rig.bus.fail_next(4 * 5, EREMOTEIO);                  // five updates' worth of NACKs: one report
  render.play(*rig.driver, carrier(175.0, 0.05, 0.6));
  ASSERT_FALSE(rig.driver->device_gone());
  EXPECT_GT(rig.bus.completed_try_transfers(), 0);

  rig.bus.set_unplugged(true);
  render.play(*rig.driver, carrier(175.0, 0.3, 0.5));
  EXPECT_TRUE(rig.driver->device_gone());
  const auto traffic_while_gone = rig.chip.traffic().size();
  rig.bus.set_unplugged(false);
  render.play(*rig.driver, carrier(175.0, 1.5, 0.5));  // longer than any reconnect interval

  EXPECT_EQ(render.exceptions, 0);
  EXPECT_EQ(render.allocations, 0u);
  EXPECT_EQ(render.frees, 0u);
  EXPECT_EQ(rig.bus.throwing_transfers(), throwing_before);  // only the real-time transfers
  EXPECT_EQ(rig.bus.reopen_count(), 0);
  EXPECT_EQ(rig.chip.resets(), resets_before);  // never initialized again from write()
  EXPECT_EQ(rig.chip.traffic().size(), traffic_while_gone);  // the bus is left alone while gone
  EXPECT_TRUE(rig.driver->device_gone());                     // until the service hands it back
  std::vector<int> error_numbers;
  EXPECT_EQ(drain_kinds(rig.driver->faults(), &error_numbers),
            (std::vector<FaultKind>{FaultKind::transfer_failed, FaultKind::device_gone}));
  EXPECT_EQ(error_numbers, (std::vector<int>{EREMOTEIO, ENODEV}));
}

ActuatorProfile piezo_profile() {
  ActuatorProfile profile;
  profile.name = "piezo";
  profile.type = ActuatorType::voice_coil;
  profile.rated_voltage_V = 95.0;
  profile.driver = DriverChip::bos1901;
  return profile;
}

TEST(RealtimePath, Bos1901WriteNeverThrowsAllocatesReopensOrRestarts) {
  FakeClock clock(1000);
  Bos1901Emulator chip(clock);
  Bos1901Driver driver(chip, clock, piezo_profile());
  driver.open(8000.0);
  chip.reserve_played(100'000);
  const int throwing_before = chip.throwing_transfers();
  RenderThreadProbe render;

  render.play(driver, carrier(250.0, 0.1, 0.9));
  chip.fail_next(2, EIO);  // transient: retried
  render.play(driver, carrier(250.0, 0.05, 0.9));
  EXPECT_GT(chip.completed_try_transfers(), 0);

  chip.set_unplugged(true);
  render.play(driver, carrier(250.0, 0.1, 0.9), [&](std::size_t count) {
    clock.advance_us(static_cast<std::int64_t>(count) * 125);  // the renderer keeps its pace
  });
  chip.set_unplugged(false);
  render.play(driver, carrier(250.0, 1.0, 0.9), [&](std::size_t count) {
    clock.advance_us(static_cast<std::int64_t>(count) * 125);
  });

  EXPECT_EQ(render.exceptions, 0);
  EXPECT_EQ(render.allocations, 0u);
  EXPECT_EQ(render.frees, 0u);
  EXPECT_EQ(chip.throwing_transfers(), throwing_before);
  EXPECT_EQ(chip.reopen_count(), 0);
  EXPECT_EQ(chip.resets(), 1);  // the one of open()
  std::vector<int> error_numbers;
  const auto kinds = drain_kinds(driver.faults(), &error_numbers);
  ASSERT_EQ(kinds.size(), 1u);
  EXPECT_EQ(kinds[0], FaultKind::device_gone);
  EXPECT_EQ(error_numbers[0], ENODEV);
}

std::vector<float> bursts(int count, double on_s, double off_s) {
  std::vector<float> drive;
  for (int i = 0; i < count; ++i) {
    const auto on = carrier(175.0, on_s, 0.7);
    drive.insert(drive.end(), on.begin(), on.end());
    drive.insert(drive.end(), static_cast<std::size_t>(off_s * 8000.0), 0.0f);
  }
  return drive;
}

TEST(RealtimePath, HidWriteNeverThrowsAllocatesOrReconnects) {
  FakeClock clock(1'000'000);
  HidHapticEmulator device(clock, 0x1234, 0x5678);
  HidHapticController controller(device, 0x1234, 0x5678, clock);
  controller.open(8000.0);
  device.reserve_triggers(10'000);
  const int opens_before = device.opens();
  RenderThreadProbe render;
  auto keep_pace = [&](std::size_t count) { clock.advance_us(static_cast<std::int64_t>(count) * 125); };

  render.play(controller, bursts(3, 0.01, 0.05), keep_pace);
  EXPECT_GT(device.completed_try_writes(), 0);
  device.set_unplugged(true);
  render.play(controller, bursts(3, 0.01, 0.05), keep_pace);
  device.set_unplugged(false);
  render.play(controller, bursts(20, 0.01, 0.1), keep_pace);  // over two seconds

  EXPECT_EQ(render.exceptions, 0);
  EXPECT_EQ(render.allocations, 0u);
  EXPECT_EQ(render.frees, 0u);
  EXPECT_EQ(device.opens(), opens_before);
  EXPECT_EQ(device.throwing_writes(), 0);
  std::vector<int> error_numbers;
  const auto kinds = drain_kinds(controller.faults(), &error_numbers);
  ASSERT_EQ(kinds.size(), 1u);
  EXPECT_EQ(kinds[0], FaultKind::device_gone);
  EXPECT_EQ(error_numbers[0], ENODEV);
}

}  // namespace
}  // namespace vimg
