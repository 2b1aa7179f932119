#include <fcntl.h>
#include <linux/spi/spidev.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <stdexcept>

#include "hal/device_error.hpp"
#include "hal/spi_bus.hpp"

namespace vimg {

int LinuxSpiBus::open_configured() const {
  const int fd = ::open(path_.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) {
    throw DeviceError(path_, "open SPI device", errno);
  }
  auto configure = [&](unsigned long request, const void* value, const char* what) {
    if (::ioctl(fd, request, value) < 0) {
      const int error_number = errno;
      ::close(fd);
      throw DeviceError(path_, what, error_number);
    }
  };
  configure(SPI_IOC_WR_MODE, &settings_.mode, "set SPI mode");
  configure(SPI_IOC_WR_BITS_PER_WORD, &settings_.bits_per_word, "set SPI bits per word");
  configure(SPI_IOC_WR_MAX_SPEED_HZ, &settings_.speed_hz, "set SPI speed");
  return fd;
}

LinuxSpiBus::LinuxSpiBus(std::string device_path, SpiSettings settings)
    : path_(std::move(device_path)), settings_(settings) {
  fd_ = open_configured();
}

LinuxSpiBus::~LinuxSpiBus() {
  if (fd_ >= 0) {
    ::close(fd_);
  }
}

int LinuxSpiBus::try_transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) noexcept {
  if (!rx.empty() && rx.size() != tx.size()) {
    return EINVAL;
  }
  spi_ioc_transfer message{};
  message.tx_buf = reinterpret_cast<std::uintptr_t>(tx.data());
  message.rx_buf = rx.empty() ? 0 : reinterpret_cast<std::uintptr_t>(rx.data());
  message.len = static_cast<std::uint32_t>(tx.size());
  message.speed_hz = settings_.speed_hz;
  message.bits_per_word = settings_.bits_per_word;
  return ::ioctl(fd_, SPI_IOC_MESSAGE(1), &message) < 0 ? errno : 0;
}

void LinuxSpiBus::transfer(std::span<const std::uint8_t> tx, std::span<std::uint8_t> rx) {
  if (!rx.empty() && rx.size() != tx.size()) {
    throw std::invalid_argument(path_ + ": SPI receive buffer must match the transmit length");
  }
  if (const int error = try_transfer(tx, rx)) {
    throw DeviceError(path_, "SPI transfer of " + std::to_string(tx.size()) + " bytes", error);
  }
}

void LinuxSpiBus::reopen() {
  const int fd = open_configured();
  if (fd_ >= 0) {
    ::close(fd_);
  }
  fd_ = fd;
}

}  // namespace vimg
