#pragma once
// Register-level emulator of a Boreas BOS1901 on SPI: the 64-entry sample FIFO played out at the
// PLAY rate on the shared clock, CONFIG (RST, OE, PLAY, BC), IC_STATUS (FIFO_SPACE, EMPTY, FULL,
// OVT) shifted out on SDO when BC selects it. It records every sample that reaches the output with
// its time, samples lost to a full FIFO, and underruns: the FIFO running empty while the output
// holds a sample other than 0 V. It can be unplugged: the chip loses power (its registers and FIFO
// go back to the power-on state) and transfers fail with ENODEV until reopen() after it is back.
//
// Threads: one thread at a time transfers (the driver's DeviceLink decides which); set_unplugged()
// and the counters may be used from any thread.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "hal/bos1901_registers.hpp"
#include "hal/spi_bus.hpp"
#include "realtime/clock.hpp"

namespace vimg {

class Bos1901Emulator final : public SpiBus {
 public:
  explicit Bos1901Emulator(Clock& clock, std::string path = "/dev/spidev-emulated");

  void transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override;
  int try_transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept override;
  void reopen() override;
  const std::string& path() const override { return path_; }

  struct PlayedSample {
    std::int64_t time_us;
    int value;  // signed 12-bit
  };
  const std::vector<PlayedSample>& played() { advance(); return played_; }
  // Room for `samples` more played samples, so that recording allocates nothing meanwhile.
  void reserve_played(std::size_t samples) { played_.reserve(played_.size() + samples); }
  int output_value() { advance(); return output_; }
  bool output_enabled() const { return (config_ & 0x10u) != 0; }
  int fifo_level() { advance(); return fifo_count_; }
  int max_fifo_level() const { return max_level_; }
  int overflows() const { return overflows_; }
  int underruns() { advance(); return underruns_; }
  int resets() const { return resets_; }
  void raise_over_temperature() { over_temperature_ = true; }
  void fail_next(int count, int error_number) { failures_left_ = count; failure_errno_ = error_number; }
  void set_unplugged(bool unplugged) { unplugged_.store(unplugged, std::memory_order_relaxed); }

  int reopen_count() const { return reopen_count_.load(std::memory_order_relaxed); }
  // Calls of transfer(), failed or not.
  int throwing_transfers() const { return throwing_transfers_.load(std::memory_order_relaxed); }
  // Calls of try_transfer() that reached the chip.
  int completed_try_transfers() const { return completed_try_transfers_.load(std::memory_order_relaxed); }

 private:
  int exchange(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept;  // 0 or errno
  void power_on_state();
  void advance();
  void execute(std::uint16_t word);
  std::uint16_t broadcast_value() const;

  Clock& clock_;
  std::string path_;
  std::uint16_t config_ = 0;
  std::array<int, bos1901::kFifoDepth> fifo_{};
  int fifo_head_ = 0;
  int fifo_count_ = 0;
  int output_ = 0;
  double sample_period_us_ = 1e6 / 8000.0;
  double play_phase_us_ = 0.0;
  std::vector<PlayedSample> played_;
  int max_level_ = 0;
  int overflows_ = 0;
  int underruns_ = 0;
  int resets_ = 0;
  bool over_temperature_ = false;
  bool was_playing_ = false;
  int failures_left_ = 0;
  int failure_errno_ = 0;
  std::atomic<bool> unplugged_{false};
  bool needs_reopen_ = false;
  std::atomic<int> reopen_count_{0};
  std::atomic<int> throwing_transfers_{0};
  std::atomic<int> completed_try_transfers_{0};
};

}  // namespace vimg
