#include "hal/emulated_i2c_bus.hpp"

#include <cerrno>

#include "hal/device_error.hpp"

namespace vimg {

I2cTarget& EmulatedI2cBus::target_or_throw(std::uint8_t address, const char* what) {
  const std::string description = std::string(what) + " address " + std::to_string(address);
  if (unplugged_ || needs_reopen_) {
    needs_reopen_ = true;
    ++failed_transfers_;
    throw DeviceError(path_, description, ENODEV);
  }
  if (failures_left_ > 0) {
    --failures_left_;
    ++failed_transfers_;
    throw DeviceError(path_, description, failure_errno_);
  }
  const auto found = targets_.find(address);
  if (found == targets_.end() || !found->second->acknowledges()) {
    ++failed_transfers_;
    throw DeviceError(path_, description + " (no acknowledge)", EREMOTEIO);
  }
  return *found->second;
}

void EmulatedI2cBus::write(std::uint8_t address, std::span<const std::uint8_t> bytes) {
  target_or_throw(address, "I2C write to").on_write(bytes);
}

void EmulatedI2cBus::write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                                std::span<std::uint8_t> in) {
  target_or_throw(address, "I2C read from").on_write_read(out, in);
}

void EmulatedI2cBus::reopen() {
  if (unplugged_) {
    throw DeviceError(path_, "open I2C adapter", ENOENT);
  }
  needs_reopen_ = false;
  ++reopen_count_;
}

}  // namespace vimg
