#include "hal/emulated_i2c_bus.hpp"

#include <cerrno>

#include "hal/device_error.hpp"

namespace vimg {

int EmulatedI2cBus::reach(std::uint8_t address, I2cTarget*& target) noexcept {
  int error = 0;
  if (unplugged_.load(std::memory_order_relaxed) || needs_reopen_) {
    needs_reopen_ = true;
    error = ENODEV;
  } else if (failures_left_ > 0) {
    --failures_left_;
    error = failure_errno_;
  } else {
    const auto found = targets_.find(address);
    if (found == targets_.end() || !found->second->acknowledges()) {
      error = EREMOTEIO;  // no acknowledge
    } else {
      target = found->second;
    }
  }
  if (error != 0) failed_transfers_.fetch_add(1, std::memory_order_relaxed);
  return error;
}

void EmulatedI2cBus::write(std::uint8_t address, std::span<const std::uint8_t> bytes) {
  throwing_transfers_.fetch_add(1, std::memory_order_relaxed);
  I2cTarget* target = nullptr;
  if (const int error = reach(address, target)) {
    throw DeviceError(path_, "I2C write to address " + std::to_string(address), error);
  }
  target->on_write(bytes);
}

void EmulatedI2cBus::write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                                std::span<std::uint8_t> in) {
  throwing_transfers_.fetch_add(1, std::memory_order_relaxed);
  I2cTarget* target = nullptr;
  if (const int error = reach(address, target)) {
    throw DeviceError(path_, "I2C read from address " + std::to_string(address), error);
  }
  target->on_write_read(out, in);
}

int EmulatedI2cBus::try_write(std::uint8_t address, std::span<const std::uint8_t> bytes) noexcept {
  I2cTarget* target = nullptr;
  if (const int error = reach(address, target)) return error;
  target->on_write(bytes);
  completed_try_transfers_.fetch_add(1, std::memory_order_relaxed);
  return 0;
}

int EmulatedI2cBus::try_write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                                   std::span<std::uint8_t> in) noexcept {
  I2cTarget* target = nullptr;
  if (const int error = reach(address, target)) return error;
  target->on_write_read(out, in);
  completed_try_transfers_.fetch_add(1, std::memory_order_relaxed);
  return 0;
}

void EmulatedI2cBus::reopen() {
  if (unplugged_.load(std::memory_order_relaxed)) {
    throw DeviceError(path_, "open I2C adapter", ENOENT);
  }
  needs_reopen_ = false;
  reopen_count_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace vimg
