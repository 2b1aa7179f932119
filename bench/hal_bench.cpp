// Hardware layer: our CPU time per DRV2605L RTP write, against the 72 us one write takes on a
// 400 kHz I2C bus (29 bit-times). Goal: at most 5 % (3.6 us). The driver runs its real-time path
// (envelope follower, loop selection, clamp, retry loop, non-throwing register write) with a ramp
// that changes the code at every update, so every update is one RTP write. And the cost of a block
// while the device is gone (the render thread skips the output until the device service hands the
// device back).
#include <benchmark/benchmark.h>

#include <cerrno>
#include <memory>
#include <vector>

#include "storage/actuator_profile.hpp"
#include "realtime/clock.hpp"
#include "hal/drv2605l_driver.hpp"
#include "hal/drv2605l_emulator.hpp"
#include "hal/drv2605l_registers.hpp"
#include "hal/emulated_i2c_bus.hpp"
#include "hal/output_spec.hpp"

namespace vimg {
namespace {

// Answers like a DRV2605L to the few reads of initialization and ignores writes: the bus costs nothing.
class NoOpI2cBus final : public I2cBus {
 public:
  void write(std::uint8_t address, std::span<const std::uint8_t> bytes) override { try_write(address, bytes); }
  void write_read(std::uint8_t address, std::span<const std::uint8_t> out, std::span<std::uint8_t> in) override {
    try_write_read(address, out, in);
  }
  int try_write(std::uint8_t, std::span<const std::uint8_t> bytes) noexcept override {
    if (gone_) return ENODEV;
    writes_ += bytes.size() >= 2 && bytes[0] == drv2605l::kRtpInput ? 1 : 0;
    return 0;
  }
  int try_write_read(std::uint8_t, std::span<const std::uint8_t> out, std::span<std::uint8_t> in) noexcept override {
    if (gone_) return ENODEV;
    const bool status = !out.empty() && out[0] == drv2605l::kStatus;
    for (auto& byte : in) byte = status ? static_cast<std::uint8_t>(drv2605l::kDeviceIdDrv2605l << 5) : 0;
    return 0;
  }
  void set_gone(bool gone) { gone_ = gone; }
  void reopen() override {}
  const std::string& path() const override { return path_; }
  std::uint64_t rtp_writes() const { return writes_; }

 private:
  std::string path_ = "/dev/null-i2c";
  std::uint64_t writes_ = 0;
  bool gone_ = false;
};

// One ramp 0 .. 1 in 256 samples: one RTP code step per sample, so with one update per sample every
// update is one RTP write (the drop at the end of the ramp takes a few updates).
std::vector<float> ramp_block() {
  std::vector<float> block(256);
  for (std::size_t i = 0; i < block.size(); ++i) block[i] = static_cast<float>(i) / 255.0f;
  return block;
}

// The envelope follower's window is one period of the resonance; at 4 kHz it is two samples, so
// the envelope follows the ramp sample by sample. The per-sample work is the same at any resonance.
ActuatorProfile bench_profile() {
  ActuatorProfile profile = default_lra_profile();
  profile.resonance_hz = 4000.0;
  return profile;
}

Drv2605lOptions bench_options() {
  Drv2605lOptions options;
  options.update_rate_hz = 8000.0;  // one update per sample
  options.pace_writes = false;      // no waiting: CPU time only
  options.status_poll_interval_s = 1e9;
  options.release_time_s = 1e-6;
  return options;
}

void BM_RtpWriteNoOpBus(benchmark::State& state) {
  NoOpI2cBus bus;
  FakeClock clock;
  Drv2605lDriver driver(bus, nullptr, clock, bench_profile(), bench_options());
  driver.open(8000.0);
  const auto block = ramp_block();
  double time_s = 0.0;
  const auto before = bus.rtp_writes();
  for (auto _ : state) {
    driver.write(block, time_s);
    time_s += 256.0 / 8000.0;
  }
  const auto writes = static_cast<double>(bus.rtp_writes() - before);
  state.counters["rtp_writes_per_256_samples"] = writes / static_cast<double>(state.iterations());
  state.counters["cpu_per_rtp_write"] =
      benchmark::Counter(writes, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_RtpWriteNoOpBus);

void BM_RtpWriteEmulator(benchmark::State& state) {
  FakeClock clock;
  Drv2605lEmulatorOptions emulator_options;
  emulator_options.bus_hz = 0.0;  // CPU time only
  emulator_options.enable_tied_high = true;
  auto chip = std::make_unique<Drv2605lEmulator>(clock, emulator_options);
  EmulatedI2cBus bus;
  bus.attach(0x5A, *chip);
  auto driver = std::make_unique<Drv2605lDriver>(bus, nullptr, clock, bench_profile(), bench_options());
  driver->open(8000.0);
  const auto block = ramp_block();
  double time_s = 0.0;
  std::uint64_t writes = 0;
  std::size_t counted = chip->traffic().size();
  for (auto _ : state) {
    driver->write(block, time_s);
    time_s += 256.0 / 8000.0;
    if (chip->traffic().size() > 1'000'000) {  // keep the recorded traffic bounded
      state.PauseTiming();
      writes += chip->traffic().size() - counted;
      driver.reset();
      chip = std::make_unique<Drv2605lEmulator>(clock, emulator_options);
      bus.attach(0x5A, *chip);
      driver = std::make_unique<Drv2605lDriver>(bus, nullptr, clock, bench_profile(), bench_options());
      driver->open(8000.0);
      counted = chip->traffic().size();
      state.ResumeTiming();
    }
  }
  writes += chip->traffic().size() - counted;
  state.counters["cpu_per_register_access"] =
      benchmark::Counter(static_cast<double>(writes), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_RtpWriteEmulator);

// One 256-sample block while the device is gone: the follower still runs, no transfer is made.
void BM_BlockWhileDeviceGone(benchmark::State& state) {
  NoOpI2cBus bus;
  FakeClock clock;
  Drv2605lDriver driver(bus, nullptr, clock, bench_profile(), bench_options());
  driver.open(8000.0);
  bus.set_gone(true);
  const auto block = ramp_block();
  double time_s = 0.0;
  driver.write(block, time_s);  // the first update finds the device gone
  if (!driver.device_gone()) state.SkipWithError("the device did not go away");
  for (auto _ : state) {
    time_s += 256.0 / 8000.0;
    driver.write(block, time_s);
  }
  state.counters["cpu_per_sample"] = benchmark::Counter(256.0 * static_cast<double>(state.iterations()),
                                                        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BlockWhileDeviceGone);

}  // namespace
}  // namespace vimg

BENCHMARK_MAIN();
