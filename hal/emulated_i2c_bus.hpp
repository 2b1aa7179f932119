#pragma once
// Test double for I2cBus: targets (chip emulators) answer at their addresses; faults can be injected.
// It counts the throwing transfers (initialization, calibration) apart from the real-time ones, and
// the reopens, so that tests can see which path a driver took.
//
// Threads: one thread at a time transfers (the driver's DeviceLink decides which); set_unplugged()
// and the counters may be used from any thread.
#include <atomic>
#include <cstdint>
#include <map>
#include <span>
#include <string>

#include "hal/i2c_bus.hpp"

namespace vimg {

// A chip on the emulated bus.
class I2cTarget {
 public:
  virtual ~I2cTarget() = default;
  // False when the chip would not acknowledge its address now (unpowered, EN low, busy).
  virtual bool acknowledges() = 0;
  virtual void on_write(std::span<const std::uint8_t> bytes) = 0;
  virtual void on_write_read(std::span<const std::uint8_t> out, std::span<std::uint8_t> in) = 0;
};

class EmulatedI2cBus final : public I2cBus {
 public:
  explicit EmulatedI2cBus(std::string path = "/dev/i2c-emulated") : path_(std::move(path)) {}

  void attach(std::uint8_t address, I2cTarget& target) { targets_[address] = &target; }

  // The next `count` transfers fail with `error_number` (e.g. EIO, EREMOTEIO) and reach no chip.
  void fail_next(int count, int error_number) {
    failures_left_ = count;
    failure_errno_ = error_number;
  }
  // While unplugged every transfer fails with ENODEV and reopen() fails with ENOENT; after it comes
  // back, transfers fail with ENODEV until reopen().
  void set_unplugged(bool unplugged) { unplugged_.store(unplugged, std::memory_order_relaxed); }

  void write(std::uint8_t address, std::span<const std::uint8_t> bytes) override;
  void write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                  std::span<std::uint8_t> in) override;
  int try_write(std::uint8_t address, std::span<const std::uint8_t> bytes) noexcept override;
  int try_write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                     std::span<std::uint8_t> in) noexcept override;
  void reopen() override;
  const std::string& path() const override { return path_; }

  int failed_transfers() const { return failed_transfers_.load(std::memory_order_relaxed); }
  int reopen_count() const { return reopen_count_.load(std::memory_order_relaxed); }
  // Calls of write() / write_read(), failed or not.
  int throwing_transfers() const { return throwing_transfers_.load(std::memory_order_relaxed); }
  // Calls of try_write() / try_write_read() that reached the chip.
  int completed_try_transfers() const { return completed_try_transfers_.load(std::memory_order_relaxed); }

 private:
  // 0 and the target, or the errno value the transfer fails with (counted).
  int reach(std::uint8_t address, I2cTarget*& target) noexcept;

  std::string path_;
  std::map<std::uint8_t, I2cTarget*> targets_;
  int failures_left_ = 0;
  int failure_errno_ = 0;
  std::atomic<bool> unplugged_{false};
  bool needs_reopen_ = false;
  std::atomic<int> failed_transfers_{0};
  std::atomic<int> reopen_count_{0};
  std::atomic<int> throwing_transfers_{0};
  std::atomic<int> completed_try_transfers_{0};
};

}  // namespace vimg
