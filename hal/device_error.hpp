#pragma once
// Errors from devices: every message names the device path and the system's errno text.
#include <stdexcept>
#include <string>

namespace vimg {

class DeviceError : public std::runtime_error {
 public:
  // `what_failed` says what we tried ("write register 0x02"); `error_number` is the errno value
  // (0 when the failure is not a system error).
  DeviceError(std::string device_path, const std::string& what_failed, int error_number);

  const std::string& device_path() const { return device_path_; }
  int error_number() const { return error_number_; }

  // True for errors that may pass: NACK (EREMOTEIO/ENXIO), EIO, EAGAIN, ETIMEDOUT, EBUSY.
  bool transient() const;
  // True when the device itself has gone (ENODEV, ENOENT, ESHUTDOWN).
  bool device_gone() const;

 private:
  std::string device_path_;
  int error_number_ = 0;
};

// The same classification for a bare errno value, for the real-time paths that return one instead
// of throwing. Both are noexcept and allocation-free.
bool transient_error(int error_number) noexcept;
bool device_gone_error(int error_number) noexcept;

// "PATH: WHAT: strerror(errno)"
std::string device_error_message(const std::string& device_path, const std::string& what_failed,
                                 int error_number);

}  // namespace vimg
