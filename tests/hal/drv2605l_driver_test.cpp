#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "hal/device_error.hpp"
#include "hal/drv2605l_registers.hpp"
#include "tests/hal/drv2605l_test_rig.hpp"

namespace vimg {
namespace {

using namespace drv2605l;
using test::Drv2605lRig;

std::vector<float> sine(double frequency_hz, double amplitude, double duration_s, double rate_hz = 8000.0) {
  std::vector<float> samples(static_cast<std::size_t>(duration_s * rate_hz));
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * frequency_hz * static_cast<double>(i) / rate_hz));
  }
  return samples;
}

void play(Drv2605lDriver& driver, const std::vector<float>& drive, double rate_hz = 8000.0, std::size_t block = 80) {
  for (std::size_t start = 0; start < drive.size(); start += block) {
    const std::size_t count = std::min(block, drive.size() - start);
    driver.write(std::span<const float>(drive).subspan(start, count), static_cast<double>(start) / rate_hz);
  }
}

std::size_t index_of_first_write(const Drv2605lEmulator& chip, std::uint8_t reg, std::uint8_t value) {
  const auto& traffic = chip.traffic();
  for (std::size_t i = 0; i < traffic.size(); ++i) {
    if (traffic[i].write && traffic[i].reg == reg && traffic[i].value == value) return i;
  }
  return traffic.size();
}

TEST(Drv2605lDriver, InitWaitsAfterEnableChecksIdResetsThenConfigures) {
  Drv2605lRig rig;
  rig.driver->initialize();
  const auto& traffic = rig.chip.traffic();
  ASSERT_FALSE(traffic.empty());
  EXPECT_TRUE(rig.chip.violations().empty()) << rig.chip.violations().front();
  // First access: STATUS read for the id, at least 250 us after EN rose.
  EXPECT_FALSE(traffic[0].write);
  EXPECT_EQ(traffic[0].reg, kStatus);
  EXPECT_GE(traffic[0].time_us - rig.chip.enable_rise_time_us(), kEnableWait_us);
  // Then the reset, and only after it the configuration.
  EXPECT_TRUE(traffic[1].write);
  EXPECT_EQ(traffic[1].reg, kMode);
  EXPECT_EQ(traffic[1].value & kModeDevReset, kModeDevReset);
  EXPECT_EQ(rig.chip.resets(), 1);
  const std::size_t reset_at = 1;
  const std::size_t rated_at = index_of_first_write(rig.chip, kRatedVoltage, rated_voltage_code(1.8, 175.0));
  const std::size_t clamp_at = index_of_first_write(rig.chip, kOdClamp, overdrive_clamp_code(2.5));
  EXPECT_GT(rated_at, reset_at);
  EXPECT_LT(rated_at, traffic.size());
  EXPECT_LT(clamp_at, traffic.size());
  EXPECT_NE(rig.chip.peek(kFeedback) & kFeedbackLra, 0);
  EXPECT_NE(rig.chip.peek(kControl3) & kControl3UnsignedRtp, 0);
  EXPECT_EQ(rig.chip.peek(kControl3) & kControl3LraOpenLoop, 0);
  EXPECT_EQ(rig.chip.peek(kOlLraPeriod), open_loop_period_code(175.0));
  EXPECT_TRUE(rig.chip.standby());
}

TEST(Drv2605lDriver, RegisterCodesFollowTheDatasheetEquations) {
  // V_rms = 20.58 mV * code * sqrt(1 - 1.5 ms * f)
  const std::uint8_t rated = rated_voltage_code(1.8, 175.0);
  EXPECT_NEAR(20.58e-3 * rated * std::sqrt(1.0 - 1.5e-3 * 175.0), 1.8, 20.58e-3);
  EXPECT_NEAR(21.96e-3 * overdrive_clamp_code(2.5), 2.5, 21.96e-3);
  EXPECT_NEAR(open_loop_period_frequency_hz(open_loop_period_code(175.0)), 175.0, 175.0 * 0.01);
  EXPECT_EQ(open_loop_period_code(10.0), 127);  // below the 7-bit range: the longest period
  EXPECT_EQ(drive_time_code(175.0), 24);        // 2.86 ms half period -> (2.86 - 0.5) / 0.1
}

TEST(Drv2605lDriver, WithoutTheWaitAfterEnableTheEmulatorRefuses) {
  FakeClock clock(1000);
  Drv2605lEmulator chip(clock);
  EmulatedI2cBus bus;
  bus.attach(0x5A, chip);
  chip.enable_pin().set(true);
  clock.advance_us(100);
  EXPECT_THROW(read_register(bus, 0x5A, kStatus), DeviceError);
  ASSERT_EQ(chip.violations().size(), 1u);
  clock.advance_us(200);
  EXPECT_EQ(read_register(bus, 0x5A, kStatus) >> 5, kDeviceIdDrv2605l);
}

class WrongChip final : public I2cTarget {
 public:
  bool acknowledges() override { return true; }
  void on_write(std::span<const std::uint8_t>) override {}
  void on_write_read(std::span<const std::uint8_t>, std::span<std::uint8_t> in) override {
    std::fill(in.begin(), in.end(), std::uint8_t{3u << 5});  // DRV2605 (not L)
  }
};

TEST(Drv2605lDriver, WrongDeviceIdIsAClearError) {
  FakeClock clock;
  EmulatedI2cBus bus("/dev/i2c-7");
  WrongChip chip;
  bus.attach(0x5A, chip);
  Drv2605lDriver driver(bus, nullptr, clock, test::lra_profile());
  try {
    driver.initialize();
    FAIL() << "expected an error";
  } catch (const DeviceError& error) {
    EXPECT_NE(std::string(error.what()).find("/dev/i2c-7"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("id 3"), std::string::npos);
  }
}

TEST(Drv2605lDriver, CalibrationIsStoredAndRestoredAtStartUp) {
  const auto file = std::filesystem::temp_directory_path() / "vimg_drv2605l_calibration_test.txt";
  std::filesystem::remove(file);
  Drv2605lOptions options;
  options.calibration_file = file;
  Drv2605lEmulatorOptions emulator;
  emulator.actuator_resonance_hz = 170.0;
  Drv2605lCalibration stored;
  {
    Drv2605lRig rig(test::lra_profile(), options, emulator);
    stored = rig.driver->calibrate();
    EXPECT_EQ(rig.chip.calibrations(), 1);
    // MODE 7 then GO, and the results read only after GO cleared.
    const std::size_t mode_at = index_of_first_write(rig.chip, kMode, kModeAutoCalibration);
    const std::size_t go_at = index_of_first_write(rig.chip, kGo, 1);
    EXPECT_LT(mode_at, go_at);
    EXPECT_LT(go_at, rig.chip.traffic().size());
    EXPECT_EQ(stored.a_cal_comp, rig.chip.peek(kACalComp));
    EXPECT_EQ(stored.a_cal_bemf, rig.chip.peek(kACalBemf));
    EXPECT_NE(stored.a_cal_comp, 0x0C);  // not the reset default
    EXPECT_TRUE(rig.chip.standby());
  }
  ASSERT_TRUE(std::filesystem::exists(file));
  Drv2605lRig fresh(test::lra_profile(), options, emulator);
  fresh.driver->initialize();
  EXPECT_EQ(fresh.chip.calibrations(), 0);
  EXPECT_EQ(fresh.chip.peek(kACalComp), stored.a_cal_comp);
  EXPECT_EQ(fresh.chip.peek(kACalBemf), stored.a_cal_bemf);
  EXPECT_EQ(fresh.chip.peek(kFeedback) & 3u, stored.bemf_gain);
  EXPECT_FALSE(fresh.driver->calibration_warning());
  std::filesystem::remove(file);
}

TEST(Drv2605lDriver, FailedCalibrationSaysWhy) {
  Drv2605lEmulatorOptions emulator;
  emulator.actuator_connected = false;
  Drv2605lRig rig(test::lra_profile(), {}, emulator);
  try {
    rig.driver->calibrate();
    FAIL() << "expected an error";
  } catch (const DeviceError& error) {
    EXPECT_NE(std::string(error.what()).find("DIAG_RESULT"), std::string::npos);
  }
  EXPECT_TRUE(rig.chip.standby());
}

TEST(Drv2605lDriver, PlaysInRtpModeAndGoesToStandbyOnStop) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  EXPECT_FALSE(rig.chip.standby());
  EXPECT_EQ(rig.chip.peek(kMode) & 7u, kModeRtp);
  play(*rig.driver, sine(175.0, 0.5, 0.2));
  const auto rtp = rig.chip.writes_to(kRtpInput);
  ASSERT_FALSE(rtp.empty());
  // The envelope of a 0.5 sine at resonance (closed loop): about half of full scale.
  EXPECT_NEAR(rig.chip.peek(kRtpInput), 128, 4);
  rig.driver->close();
  EXPECT_TRUE(rig.chip.standby());
  EXPECT_EQ(rig.chip.peek(kRtpInput), 0);
  const auto last = rig.chip.traffic().back();
  EXPECT_TRUE(last.write);
  EXPECT_EQ(last.reg, kMode);
  rig.driver->close();  // safe twice
  EXPECT_TRUE(rig.chip.violations().empty());
}

TEST(Drv2605lDriver, WritesArePacedAtTheUpdateRate) {
  Drv2605lOptions options;
  options.update_rate_hz = 1000.0;
  Drv2605lRig rig(test::lra_profile(), options);
  rig.driver->open(8000.0);
  // A slow ramp changes the code at every update.
  std::vector<float> ramp(8000);
  for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = static_cast<float>(i) / 8000.0f;
  play(*rig.driver, ramp);
  const auto rtp = rig.chip.writes_to(kRtpInput);
  ASSERT_GT(rtp.size(), 250u);  // one write per code step of the ramp
  for (std::size_t i = 2; i < rtp.size(); ++i) {
    EXPECT_GE(rtp[i].time_us - rtp[i - 1].time_us, 999) << "write " << i;
  }
}

TEST(Drv2605lDriver, ResonantCarrierStaysClosedLoopOffResonanceFollowsInOpenLoop) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  play(*rig.driver, sine(175.0, 0.8, 0.1));
  EXPECT_FALSE(rig.driver->open_loop());
  EXPECT_EQ(rig.chip.peek(kControl3) & kControl3LraOpenLoop, 0);
  // A texture at 120 Hz (a finger over a surface): open loop at 120 Hz.
  play(*rig.driver, sine(120.0, 0.8, 0.1));
  EXPECT_TRUE(rig.driver->open_loop());
  EXPECT_NE(rig.chip.peek(kControl3) & kControl3LraOpenLoop, 0);
  EXPECT_NEAR(open_loop_period_frequency_hz(rig.chip.peek(kOlLraPeriod)), 120.0, 120.0 * 0.03);
  // The finger speeds up: 140 Hz follows.
  play(*rig.driver, sine(140.0, 0.8, 0.1));
  EXPECT_NEAR(open_loop_period_frequency_hz(rig.chip.peek(kOlLraPeriod)), 140.0, 140.0 * 0.03);
  // Back on resonance: closed loop again.
  play(*rig.driver, sine(175.0, 0.8, 0.1));
  EXPECT_FALSE(rig.driver->open_loop());
}

TEST(Drv2605lDriver, ShortPulsesAreStretchedToTheMinimumPulse) {
  auto profile = test::lra_profile();
  profile.min_pulse_s = 0.020;
  Drv2605lRig rig(profile);
  rig.driver->open(8000.0);
  std::vector<float> drive = sine(175.0, 0.8, 0.005);  // 5 ms burst
  drive.resize(8000 / 10, 0.0f);                         // then 95 ms of silence
  const std::int64_t start = rig.clock.now_us();
  play(*rig.driver, drive);
  const auto rtp = rig.chip.writes_to(kRtpInput);
  ASSERT_GE(rtp.size(), 2u);
  std::int64_t on_us = 0, off_us = 0;
  for (const auto& w : rtp) {
    if (w.value > 0 && on_us == 0) on_us = w.time_us;
    if (w.value == 0 && on_us != 0) { off_us = w.time_us; break; }
  }
  ASSERT_GT(on_us, start);
  EXPECT_GE(off_us - on_us, 20'000);
}

// The safety property: whatever the drive, no RTP write exceeds the clamp of the loop mode in force.
TEST(Drv2605lDriver, NeverWritesAnRtpCodeAboveTheClampOverRandomDrive) {
  for (const bool signed_rtp : {false, true}) {
    Drv2605lOptions options;
    options.signed_rtp = signed_rtp;
    Drv2605lRig rig(test::lra_profile(), options);
    rig.driver->open(8000.0);
    std::mt19937 random(signed_rtp ? 7u : 11u);
    std::uniform_real_distribution<double> frequency(20.0, 600.0);
    std::uniform_real_distribution<double> amplitude(0.0, 3.0);  // includes out-of-range drive
    std::uniform_real_distribution<double> duration(0.005, 0.08);
    std::uniform_real_distribution<double> noise(-1.5, 1.5);
    std::uniform_int_distribution<int> kind(0, 2);
    std::vector<float> drive;
    for (int segment = 0; segment < 200; ++segment) {
      const int k = kind(random);
      const double f = frequency(random), a = amplitude(random), d = duration(random);
      const auto n = static_cast<std::size_t>(d * 8000.0);
      for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / 8000.0;
        double x = 0.0;
        if (k == 0) x = a * std::sin(2.0 * std::numbers::pi * f * t);
        else if (k == 1) x = noise(random);
        else x = a * std::sin(2.0 * std::numbers::pi * f * t) * std::exp(-t / 0.01);
        drive.push_back(static_cast<float>(x));
      }
    }
    play(*rig.driver, drive);
    rig.driver->close();
    const std::uint8_t full = signed_rtp ? 127 : 255;
    const auto open_clamp = static_cast<std::uint8_t>(std::floor(full * 1.8 / 2.5));
    bool open_loop = false;
    int open_loop_writes = 0, rtp_writes = 0;
    for (const auto& access : rig.chip.traffic()) {
      if (!access.write) continue;
      if (access.reg == kControl3) open_loop = (access.value & kControl3LraOpenLoop) != 0;
      if (access.reg == kRtpInput) {
        ++rtp_writes;
        open_loop_writes += open_loop ? 1 : 0;
        ASSERT_LE(access.value, open_loop ? open_clamp : full) << "at " << access.time_us << " us";
      }
    }
    EXPECT_GT(rtp_writes, 100);
    EXPECT_GT(open_loop_writes, 10);  // both modes were exercised
  }
}

TEST(Drv2605lDriver, TraceCsvHasOneRowPerAccess) {
  Drv2605lRig rig;
  rig.driver->open(8000.0);
  play(*rig.driver, sine(175.0, 0.5, 0.05));
  rig.driver->close();
  std::ostringstream csv;
  rig.chip.write_trace_csv(csv);
  const std::string text = csv.str();
  EXPECT_EQ(text.rfind("time_s,op,register,value\n", 0), 0u);
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), rig.chip.traffic().size() + 1);
  EXPECT_NE(text.find(",write,0x02,"), std::string::npos);
}

}  // namespace
}  // namespace vimg
