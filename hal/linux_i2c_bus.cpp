#include <fcntl.h>
#include <linux/i2c-dev.h>
#include <linux/i2c.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <utility>

#include "hal/device_error.hpp"
#include "hal/i2c_bus.hpp"

namespace vimg {

namespace {

int open_adapter(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) {
    throw DeviceError(path, "open I2C adapter", errno);
  }
  return fd;
}

}  // namespace

LinuxI2cBus::LinuxI2cBus(std::string device_path) : path_(std::move(device_path)), fd_(open_adapter(path_)) {}

LinuxI2cBus::~LinuxI2cBus() {
  if (fd_ >= 0) {
    ::close(fd_);
  }
}

int LinuxI2cBus::try_write(std::uint8_t address, std::span<const std::uint8_t> bytes) noexcept {
  i2c_msg message{};
  message.addr = address;
  message.flags = 0;
  message.len = static_cast<__u16>(bytes.size());
  message.buf = const_cast<__u8*>(bytes.data());  // the kernel only reads a write message
  i2c_rdwr_ioctl_data transfer{&message, 1};
  return ::ioctl(fd_, I2C_RDWR, &transfer) < 0 ? errno : 0;
}

int LinuxI2cBus::try_write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                                std::span<std::uint8_t> in) noexcept {
  i2c_msg messages[2]{};
  messages[0].addr = address;
  messages[0].flags = 0;
  messages[0].len = static_cast<__u16>(out.size());
  messages[0].buf = const_cast<__u8*>(out.data());
  messages[1].addr = address;
  messages[1].flags = I2C_M_RD;
  messages[1].len = static_cast<__u16>(in.size());
  messages[1].buf = in.data();
  i2c_rdwr_ioctl_data transfer{messages, 2};
  return ::ioctl(fd_, I2C_RDWR, &transfer) < 0 ? errno : 0;
}

void LinuxI2cBus::write(std::uint8_t address, std::span<const std::uint8_t> bytes) {
  if (const int error = try_write(address, bytes)) {
    throw DeviceError(path_, "I2C write to address " + std::to_string(address), error);
  }
}

void LinuxI2cBus::write_read(std::uint8_t address, std::span<const std::uint8_t> out,
                             std::span<std::uint8_t> in) {
  if (const int error = try_write_read(address, out, in)) {
    throw DeviceError(path_, "I2C read from address " + std::to_string(address), error);
  }
}

void LinuxI2cBus::reopen() {
  const int fd = open_adapter(path_);
  if (fd_ >= 0) {
    ::close(fd_);
  }
  fd_ = fd;
}

}  // namespace vimg
