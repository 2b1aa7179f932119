#pragma once
// An SPI bus with one chip select. Real: LinuxSpiBus (spidev, SPI_IOC_MESSAGE). Test double: the
// chip emulators that implement it (Bos1901Emulator).
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
  const std::string& path() const override { return path_; }

 private:
  std::string path_;
  SpiSettings settings_;
  int fd_ = -1;
};

}  // namespace vimg
