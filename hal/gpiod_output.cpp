#include <gpiod.h>

#include <cerrno>

#include "hal/device_error.hpp"
#include "hal/gpio_output.hpp"

namespace vimg {

GpiodOutput::GpiodOutput(const std::string& chip_name, unsigned line_offset, const std::string& consumer,
                         bool initial_high)
    : name_(chip_name + ":" + std::to_string(line_offset)) {
  chip_ = gpiod_chip_open_by_name(chip_name.c_str());
  if (chip_ == nullptr) {
    throw DeviceError("/dev/" + chip_name, "open GPIO chip", errno);
  }
  line_ = gpiod_chip_get_line(chip_, line_offset);
  if (line_ == nullptr) {
    const int error_number = errno;
    gpiod_chip_close(chip_);
    throw DeviceError("/dev/" + chip_name, "get line " + std::to_string(line_offset), error_number);
  }
  if (gpiod_line_request_output(line_, consumer.c_str(), initial_high ? 1 : 0) < 0) {
    const int error_number = errno;
    gpiod_chip_close(chip_);
    throw DeviceError("/dev/" + chip_name, "request line " + std::to_string(line_offset) + " as output",
                      error_number);
  }
}

GpiodOutput::~GpiodOutput() {
  gpiod_line_release(line_);
  gpiod_chip_close(chip_);
}

void GpiodOutput::set(bool high) {
  if (gpiod_line_set_value(line_, high ? 1 : 0) < 0) {
    throw DeviceError("/dev/" + name_, "set line value", errno);
  }
}

}  // namespace vimg
