#pragma once
// An SPI bus with one chip select. Real: LinuxSpiBus (spidev, SPI_IOC_MESSAGE). Test double: the
// chip emulators that implement it (Bos1901Emulator).
//
// transfer() throws DeviceError with a message (initialization, on the control or the device
// service thread); try_transfer() returns 0 or the errno value and never throws, allocates or
// locks (the real-time thread). One thread at a time uses a bus; drivers hand it between the render
// thread and the service thread with a DeviceLink (hal/device_link.hpp).
#include <cstdint>
#include <span>
#include <string>

namespace vimg {

class SpiBus {
 public:
  virtual ~SpiBus() = default;
  // One full-duplex transfer with chip select held low throughout; rx may be empty (write only),
  // otherwise it has tx.size() bytes. Throws DeviceError.
  virtual void transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) = 0;
  // The same for the real-time thread: 0, or the errno value (EINVAL for a bad rx length).
  virtual int try_transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept = 0;
  // Closes and opens the device again with the same settings (after it went away). Throws.
  virtual void reopen() = 0;
  virtual const std::string& path() const = 0;
};

struct SpiSettings {
  std::uint8_t mode = 0;          // SPI_MODE_0..3 (CPOL, CPHA)
  std::uint32_t speed_hz = 1'000'000;
  std::uint8_t bits_per_word = 8;
};

// /dev/spidevB.C through spidev.
class LinuxSpiBus final : public SpiBus {
 public:
  LinuxSpiBus(std::string device_path, SpiSettings settings);  // throws DeviceError
  ~LinuxSpiBus() override;
  LinuxSpiBus(const LinuxSpiBus&) = delete;
  LinuxSpiBus& operator=(const LinuxSpiBus&) = delete;

  void transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) override;
  int try_transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept override;
  void reopen() override;
  const std::string& path() const override { return path_; }

 private:
  int open_configured() const;  // throws DeviceError

  std::string path_;
  SpiSettings settings_;
  int fd_ = -1;
};

}  // namespace vimg
