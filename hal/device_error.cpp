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

bool DeviceError::transient() const {
  switch (error_number_) {
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

bool DeviceError::device_gone() const {
  return error_number_ == ENODEV || error_number_ == ENOENT || error_number_ == ESHUTDOWN;
}

}  // namespace vimg
