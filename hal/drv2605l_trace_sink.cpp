#include "hal/drv2605l_trace_sink.hpp"

#include <sstream>
#include <stdexcept>

#include "hal/device_error.hpp"
#include "storage/atomic_file.hpp"

namespace vimg {

Drv2605lTraceSink::Drv2605lTraceSink(DriveSink& next, const ActuatorProfile& profile,
                                     std::filesystem::path trace_path)
    : next_(next), trace_path_(std::move(trace_path)), clock_(0), chip_(clock_) {
  if (profile.type != ActuatorType::lra || profile.driver != DriverChip::drv2605l) {
    throw std::invalid_argument("--register-trace needs an LRA profile with driver chip=\"drv2605l\"; '" +
                                profile.name + "' is " + std::string(to_string(profile.type)) + " on " +
                                std::string(to_string(profile.driver)));
  }
  ActuatorProfile emulated = profile;
  emulated.address = 0x5A;
  bus_.attach(0x5A, chip_);
  driver_ = std::make_unique<Drv2605lDriver>(bus_, &chip_.enable_pin(), clock_, emulated);
}

void Drv2605lTraceSink::open(double sample_rate_hz) {
  next_.open(sample_rate_hz);
  closed_ = false;
  try {
    driver_->open(sample_rate_hz);
  } catch (const DeviceError& error) {
    error_ = trace_path_.string() + ": " + error.what();
  }
}

void Drv2605lTraceSink::write(std::span<const float> drive, double block_start_time_s) {
  next_.write(drive, block_start_time_s);
  if (!error_) driver_->write(drive, block_start_time_s);
}

void Drv2605lTraceSink::close() {
  next_.close();
  if (closed_) return;
  closed_ = true;
  driver_->close();
  std::ostringstream text;
  chip_.write_trace_csv(text);
  if (auto error = write_file_atomically(trace_path_, text.str(), new_file_mode_)) error_ = "cannot write the register trace: " + *error;
}

}  // namespace vimg
