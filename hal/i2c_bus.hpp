#pragma once
// An I2C bus master. Real: LinuxI2cBus (i2c-dev, ioctl I2C_RDWR). Test double: EmulatedI2cBus,
// where register-level emulators of the chips answer.
//
// Two ways to transfer:
//   - write() / write_read() throw DeviceError with a message: for initialization and calibration,
//     on the control or the device service thread;
//   - try_write() / try_write_read() return 0 or the errno value and never throw, allocate or lock:
//     for the real-time thread, which may only wait on the device itself.
// Threads: one thread at a time uses a bus; drivers hand it between the render thread and the
// service thread with a DeviceLink (hal/device_link.hpp).
#include <cstdint>
#include <span>
#include <string>

namespace vimg {

class I2cBus {
 public:
  virtual ~I2cBus() = default;
  // One transfer: START, address+W, bytes, STOP. Throws DeviceError (NACK: EREMOTEIO or ENXIO).
  virtual void write(std::uint8_t address, std::span<const std::uint8_t> bytes) = 0;
  // One combined transfer: START, address+W, out, repeated START, address+R, in, STOP.
  virtual void write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                          std::span<std::uint8_t> in) = 0;
  // The same transfers for the real-time thread: 0, or the errno value of the failure.
  virtual int try_write(std::uint8_t address, std::span<const std::uint8_t> bytes) noexcept = 0;
  virtual int try_write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                             std::span<std::uint8_t> in) noexcept = 0;
  // Closes and opens the adapter again (after the device node went away). Throws on failure.
  virtual void reopen() = 0;
  virtual const std::string& path() const = 0;
};

void write_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg, std::uint8_t value);
std::uint8_t read_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg);
// Real-time forms: 0 or the errno value; `value` is set only on success.
int try_write_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg, std::uint8_t value) noexcept;
int try_read_register(I2cBus& bus, std::uint8_t address, std::uint8_t reg, std::uint8_t& value) noexcept;

// /dev/i2c-N through i2c-dev.
class LinuxI2cBus final : public I2cBus {
 public:
  explicit LinuxI2cBus(std::string device_path);  // throws DeviceError
  ~LinuxI2cBus() override;
  LinuxI2cBus(const LinuxI2cBus&) = delete;
  LinuxI2cBus& operator=(const LinuxI2cBus&) = delete;

  void write(std::uint8_t address, std::span<const std::uint8_t> bytes) override;
  void write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                  std::span<std::uint8_t> in) override;
  int try_write(std::uint8_t address, std::span<const std::uint8_t> bytes) noexcept override;
  int try_write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                     std::span<std::uint8_t> in) noexcept override;
  void reopen() override;
  const std::string& path() const override { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace vimg
