#pragma once
// For `vimg render --actuator PROFILE --register-trace FILE.csv`: forwards the drive to the render's
// own sink and also plays it through the DRV2605L driver into the register-level emulator, on a
// simulated clock that follows the render's sample times. close() writes the emulator's timestamped
// register traffic (time_s,op,register,value), so hardware behaviour is file-testable.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "storage/actuator_profile.hpp"
#include "realtime/clock.hpp"
#include "hal/drv2605l_driver.hpp"
#include "hal/drv2605l_emulator.hpp"
#include "hal/emulated_i2c_bus.hpp"
#include "player/drive_sink.hpp"
#include "storage/atomic_file.hpp"

namespace vimg {

class Drv2605lTraceSink final : public DriveSink {
 public:
  // Throws std::invalid_argument when the profile is not an LRA on a DRV2605L.
  Drv2605lTraceSink(DriveSink& next, const ActuatorProfile& profile, std::filesystem::path trace_path);

  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;
  double output_latency_s() const override { return next_.output_latency_s(); }

  const std::optional<std::string>& error() const { return error_; }  // "FILE: problem"
  // The permission bits of the trace file if it is new (NewFileMode::of the image it is made from).
  void set_new_file_mode(NewFileMode mode) { new_file_mode_ = mode; }

 private:
  DriveSink& next_;
  std::filesystem::path trace_path_;
  NewFileMode new_file_mode_;
  FakeClock clock_;
  EmulatedI2cBus bus_{"/dev/i2c-emulated"};
  Drv2605lEmulator chip_;
  std::unique_ptr<Drv2605lDriver> driver_;
  bool closed_ = false;
  std::optional<std::string> error_;
};

}  // namespace vimg
