#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <cerrno>
#include <string>

#include "hal/device_service.hpp"
#include "hal/hid_haptic_controller.hpp"
#include "hal/hid_haptic_emulator.hpp"

namespace vimg {
namespace {

using namespace hid_haptics;

std::vector<float> burst(double duration_s, double amplitude) {
  std::vector<float> samples(static_cast<std::size_t>(duration_s * 8000.0));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * 175.0 * static_cast<double>(i) / 8000.0));
  }
  return samples;
}

struct Rig {
  FakeClock clock{1'000'000};
  HidHapticEmulator device{clock, 0x1234, 0x5678};
  HidHapticController controller{device, 0x1234, 0x5678, clock};
  double time_s = 0.0;
  void play(const std::vector<float>& drive) {
    for (std::size_t start = 0; start < drive.size(); start += 80) {
      const std::size_t count = std::min<std::size_t>(80, drive.size() - start);
      controller.write(std::span<const float>(drive).subspan(start, count), time_s);
      time_s += static_cast<double>(count) / 8000.0;
      clock.advance_us(static_cast<std::int64_t>(count) * 125);
    }
  }
};

TEST(HidHaptics, ConnectReadsTheWaveformListAndDurations) {
  Rig rig;
  rig.controller.connect();
  const auto& waveforms = rig.controller.waveforms();
  ASSERT_EQ(waveforms.size(), 2u);
  EXPECT_EQ(waveforms[0].usage, kWaveformClick);
  EXPECT_EQ(waveforms[0].ordinal, 3);
  EXPECT_EQ(waveforms[0].duration_ms, 15);
  EXPECT_EQ(waveforms[1].usage, kWaveformBuzz);
  EXPECT_EQ(waveforms[1].ordinal, 4);
  EXPECT_EQ(rig.controller.device_path(), rig.device.path());
}

TEST(HidHaptics, ManualTriggerCarriesIntensity) {
  Rig rig;
  rig.controller.connect();
  rig.controller.trigger(kWaveformBuzz, 0.42, 3, 100);
  ASSERT_EQ(rig.device.triggers().size(), 1u);
  const auto& trigger = rig.device.triggers()[0];
  EXPECT_EQ(trigger.waveform, kWaveformBuzz);
  EXPECT_EQ(trigger.intensity_percent, 42);
  EXPECT_EQ(trigger.repeat_count, 3);
  EXPECT_EQ(trigger.retrigger_period_ms, 100);
  EXPECT_THROW(rig.controller.trigger(kWaveformRumble, 1.0), std::invalid_argument);
}

TEST(HidHaptics, MissingDeviceIsAClearError) {
  FakeClock clock;
  HidHapticEmulator device(clock, 0x1234, 0x5678);
  HidHapticController controller(device, 0x1234, 0x9999, clock);
  try {
    controller.connect();
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("1234:9999"), std::string::npos) << error.what();
  }
}

TEST(HidHaptics, ShortBurstIsAClickSustainedDriveABuzzThatStops) {
  Rig rig;
  rig.controller.open(8000.0);
  // A DOT crossing: 10 ms burst, then silence.
  rig.play(burst(0.010, 0.6));
  rig.play(std::vector<float>(800, 0.0f));
  // A SURFACE: 200 ms of drive, then silence.
  rig.play(burst(0.200, 0.8));
  rig.play(std::vector<float>(800, 0.0f));
  rig.controller.close();
  const auto& triggers = rig.device.triggers();
  ASSERT_GE(triggers.size(), 4u);
  EXPECT_EQ(triggers[0].waveform, kWaveformClick);
  EXPECT_NEAR(triggers[0].intensity_percent, 60, 8);
  EXPECT_EQ(triggers[1].waveform, kWaveformClick);  // the surface's onset
  EXPECT_EQ(triggers[2].waveform, kWaveformBuzz);
  EXPECT_NEAR(triggers[2].intensity_percent, 80, 8);
  EXPECT_EQ(triggers[2].retrigger_period_ms, 50);
  EXPECT_GE(triggers[2].time_us - triggers[1].time_us, 15'000);  // after the click's duration
  bool stopped_after_buzz = false;
  for (std::size_t i = 3; i < triggers.size(); ++i) stopped_after_buzz |= triggers[i].waveform == kWaveformStop;
  EXPECT_TRUE(stopped_after_buzz);
  EXPECT_EQ(triggers.back().waveform, kWaveformStop);
}

TEST(HidHaptics, UnpluggedDeviceIsReportedAndTheServiceReconnectsIt) {
  Rig rig;
  DeviceServiceOptions service_options;
  service_options.first_reconnect_interval_s = 0.5;
  DeviceService service(service_options);
  service.add(rig.controller);
  auto service_time_ns = [&] { return rig.clock.now_us() * 1000; };  // one thread: the fake clock
  rig.controller.open(8000.0);
  rig.device.set_unplugged(true);
  rig.play(burst(0.05, 0.6));
  EXPECT_TRUE(rig.controller.device_gone());
  service.poll(service_time_ns());
  EXPECT_EQ(service.take_messages(),
            (std::vector<std::string>{describe({FaultKind::device_gone, ENODEV, 0}, rig.device.path())}));
  rig.device.set_unplugged(false);
  rig.play(std::vector<float>(8000, 0.0f));  // a second: the render thread does not reconnect
  EXPECT_TRUE(rig.controller.device_gone());
  EXPECT_EQ(rig.device.opens(), 1);
  service.poll(service_time_ns());
  EXPECT_FALSE(rig.controller.device_gone());
  EXPECT_EQ(rig.device.opens(), 2);
  EXPECT_EQ(service.take_messages(),
            (std::vector<std::string>{describe({FaultKind::reconnected, 0, 0}, rig.device.path())}));
  const auto before = rig.device.triggers().size();
  rig.play(burst(0.01, 0.6));
  EXPECT_GT(rig.device.triggers().size(), before);
}

}  // namespace
}  // namespace vimg
