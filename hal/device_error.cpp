#include "hal/device_error.hpp"

#include <cerrno>
#include <cstring>
#include <utility>

namespace vimg {

std::string device_error_message(const std::string& device_path, const std::string& what_failed,
                                 int error_number) {
  std::string message = device_path + ": " + what_failed;
  if (error_number != 0) {
    message += ": ";
    message += std::strerror(error_number);
  }
  return message;
}

DeviceError::DeviceError(std::string device_path, const std::string& what_failed, int error_number)
    : std::runtime_error(device_error_message(device_path, what_failed, error_number)),
      device_path_(std::move(device_path)),
      error_number_(error_number) {}

bool transient_error(int error_number) noexcept {
  switch (error_number) {
    case EREMOTEIO:
    case ENXIO:
    case EIO:
    case EAGAIN:
    case ETIMEDOUT:
    case EBUSY:
      return true;
    default:
      return false;
  }
}

bool device_gone_error(int error_number) noexcept {
  return error_number == ENODEV || error_number == ENOENT || error_number == ESHUTDOWN;
}

bool DeviceError::transient() const { return transient_error(error_number_); }

bool DeviceError::device_gone() const { return device_gone_error(error_number_); }

}  // namespace vimg
