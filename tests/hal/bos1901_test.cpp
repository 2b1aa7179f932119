#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <numbers>
#include <vector>

#include "hal/bos1901_driver.hpp"
#include "hal/bos1901_emulator.hpp"
#include "hal/bos1901_registers.hpp"
#include "hal/rest_on_exit.hpp"

namespace vimg {
namespace {

ActuatorProfile piezo_profile() {
  ActuatorProfile profile;
  profile.name = "piezo";
  profile.type = ActuatorType::voice_coil;
  profile.rated_voltage_V = 95.0;  // full scale
  profile.driver = DriverChip::bos1901;
  return profile;
}

std::vector<float> sine(double frequency_hz, double amplitude, std::size_t count) {
  std::vector<float> samples(count);
  for (std::size_t i = 0; i < count; ++i) {
    samples[i] = static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * frequency_hz * static_cast<double>(i) / 8000.0));
  }
  return samples;
}

TEST(Bos1901, SampleCodesAreTwelveBitTwosComplement) {
  EXPECT_EQ(bos1901::sample_code(0.0), 0);
  EXPECT_EQ(bos1901::sample_code(1.0), 0x7FF);
  EXPECT_EQ(bos1901::sample_code(-1.0), 0x801);
  EXPECT_EQ(bos1901::sample_code(5.0), 0x7FF);  // saturates
  EXPECT_EQ(bos1901::sample_value(0x801), -2047);
  EXPECT_EQ(bos1901::play_code_for_rate(8000.0), 7);
  EXPECT_EQ(bos1901::play_code_for_rate(1'024'000.0), 0);
  EXPECT_EQ(bos1901::play_code_for_rate(44100.0), -1);
}

TEST(Bos1901, StreamsEverySampleInOrderStartingAndEndingAtZeroVolts) {
  FakeClock clock(1000);
  Bos1901Emulator chip(clock);
  const auto drive = sine(250.0, 0.9, 4000);
  {
    Bos1901Driver driver(chip, clock, piezo_profile());
    driver.open(8000.0);
    for (std::size_t start = 0; start < drive.size(); start += 160) {
      driver.write(std::span<const float>(drive).subspan(start, 160), static_cast<double>(start) / 8000.0);
    }
    driver.close();
    EXPECT_EQ(driver.underruns(), 0u);
  }
  EXPECT_EQ(chip.resets(), 1);
  EXPECT_EQ(chip.overflows(), 0);
  EXPECT_LE(chip.max_fifo_level(), bos1901::kFifoDepth);
  EXPECT_GT(chip.max_fifo_level(), bos1901::kFifoDepth / 2);  // the FIFO is kept full
  EXPECT_FALSE(chip.output_enabled());
  const auto& played = chip.played();
  ASSERT_EQ(played.size(), drive.size() + 2);
  EXPECT_EQ(played.front().value, 0);
  EXPECT_EQ(played.back().value, 0);
  for (std::size_t i = 0; i < drive.size(); ++i) {
    ASSERT_EQ(played[i + 1].value, bos1901::sample_value(bos1901::sample_code(drive[i]))) << i;
  }
  // Played at the PLAY rate: 125 us apart.
  for (std::size_t i = 2; i < played.size(); ++i) {
    ASSERT_NEAR(static_cast<double>(played[i].time_us - played[i - 1].time_us), 125.0, 1.0);
  }
  EXPECT_EQ(chip.output_value(), 0);
}

TEST(Bos1901, ProfileVoltageScalesTheSamples) {
  FakeClock clock;
  Bos1901Emulator chip(clock);
  auto profile = piezo_profile();
  profile.rated_voltage_V = 47.5;  // half of full scale
  Bos1901Driver driver(chip, clock, profile);
  driver.open(8000.0);
  const std::vector<float> ones(32, 1.0f);
  driver.write(ones, 0.0);
  driver.close();
  int peak = 0;
  for (const auto& sample : chip.played()) peak = std::max(peak, sample.value);
  EXPECT_NEAR(peak, 1024, 1);
}

TEST(Bos1901, UnderrunIsReportedAndTheStreamRestartsFromZero) {
  FakeClock clock;
  Bos1901Emulator chip(clock);
  Bos1901Driver driver(chip, clock, piezo_profile());
  driver.open(8000.0);
  const std::vector<float> level(40, 0.5f);
  driver.write(level, 0.0);
  clock.advance_us(20'000);  // the renderer is 20 ms late: the 40 samples ran out
  driver.write(level, 0.02);
  driver.close();
  EXPECT_EQ(driver.underruns(), 1u);
  EXPECT_EQ(chip.underruns(), 1);
  const auto event = driver.faults().pop();
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, FaultKind::underrun);
  // After the gap the first played sample is 0 V again.
  const auto& played = chip.played();
  std::size_t gap = 0;
  for (std::size_t i = 1; i < played.size(); ++i) {
    if (played[i].time_us - played[i - 1].time_us > 1000) gap = i;
  }
  ASSERT_GT(gap, 0u);
  EXPECT_EQ(played[gap].value, 0);
  EXPECT_NE(played[gap + 1].value, 0);
}

TEST(Bos1901, OtherRatesAreRefusedClearly) {
  FakeClock clock;
  Bos1901Emulator chip(clock, "/dev/spidev0.0");
  Bos1901Driver driver(chip, clock, piezo_profile());
  try {
    driver.open(44100.0);
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("/dev/spidev0.0"), std::string::npos);
  }
}

TEST(Bos1901, OverTemperatureStopsOutput) {
  FakeClock clock;
  Bos1901Emulator chip(clock);
  Bos1901Driver driver(chip, clock, piezo_profile());
  driver.open(8000.0);
  driver.write(sine(250.0, 0.5, 200), 0.0);
  chip.raise_over_temperature();
  driver.write(sine(250.0, 0.5, 200), 0.025);
  EXPECT_TRUE(driver.output_stopped());
  EXPECT_FALSE(chip.output_enabled());
  EXPECT_EQ(chip.output_value(), 0);
  const auto event = driver.faults().pop();
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, FaultKind::over_temperature);
}

TEST(Bos1901, TransientSpiErrorsAreRetried) {
  FakeClock clock;
  Bos1901Emulator chip(clock);
  Bos1901Driver driver(chip, clock, piezo_profile());
  driver.open(8000.0);
  chip.fail_next(2, EIO);
  driver.write(sine(250.0, 0.5, 100), 0.0);
  driver.close();
  EXPECT_EQ(chip.played().size(), 102u);
}

TEST(Bos1901, SignalPutsItToRest) {
  clear_rest_request();
  FakeClock clock;
  Bos1901Emulator chip(clock);
  Bos1901Driver driver(chip, clock, piezo_profile());
  driver.open(8000.0);
  driver.write(sine(250.0, 0.5, 100), 0.0);
  {
    SignalRestScope scope;
    std::raise(SIGINT);
    driver.write(sine(250.0, 0.5, 100), 0.0125);
  }
  clear_rest_request();
  EXPECT_FALSE(chip.output_enabled());
  EXPECT_EQ(chip.output_value(), 0);
}

// The FIFO paces the renderer (DriveSink::paces_stream()): write() returns when the chip has room,
// so a block takes its own duration on the chip's clock in the steady state. When no sample can
// reach the chip (gone, stopped) write() still takes the block's duration, or the renderer, which
// never sleeps for a sink that paces the stream, would spin.
TEST(Bos1901, PacesTheStreamEvenWhileItsOutputIsSkipped) {
  FakeClock clock(1000);
  Bos1901Emulator chip(clock);
  Bos1901Driver driver(chip, clock, piezo_profile());
  EXPECT_TRUE(driver.paces_stream());
  driver.open(8000.0);
  const auto block = sine(250.0, 0.5, 80);  // 10 ms
  for (int k = 0; k < 10; ++k) driver.write(block, 0.01 * k);  // fills the FIFO first
  auto block_duration_us = [&](double start_s) {
    const auto before = clock.now_us();
    driver.write(block, start_s);
    return clock.now_us() - before;
  };
  EXPECT_NEAR(static_cast<double>(block_duration_us(0.1)), 10'000.0, 130.0);  // streaming
  chip.set_unplugged(true);
  EXPECT_NEAR(static_cast<double>(block_duration_us(0.11)), 10'000.0, 130.0);  // lost now
  ASSERT_TRUE(driver.device_gone());
  EXPECT_NEAR(static_cast<double>(block_duration_us(0.12)), 10'000.0, 130.0);  // skipped
  chip.set_unplugged(false);
  driver.reconnect();  // what the device service does
  EXPECT_NEAR(static_cast<double>(block_duration_us(0.13)), 2'000.0, 2'000.0);  // the FIFO refills
  chip.raise_over_temperature();
  block_duration_us(0.14);
  ASSERT_TRUE(driver.output_stopped());
  EXPECT_NEAR(static_cast<double>(block_duration_us(0.15)), 10'000.0, 130.0);  // stopped
}

}  // namespace
}  // namespace vimg
