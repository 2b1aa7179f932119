#pragma once
// TI DRV2605L in real-time playback (RTP) mode driving an LRA: a DriveSink.
//
// Initialization (initialize(), or the first open()): EN high, wait 250 us, check DEVICE_ID = 7 in
// STATUS, DEV_RESET and wait for it to clear, then LRA mode (FEEDBACK bit 7, braking factor from
// the profile), RATED_VOLTAGE and OD_CLAMP from the profile, DRIVE_TIME = half the resonance period,
// RTP data format (CONTROL3 bit 3), OL_LRA_PERIOD at resonance, the stored calibration if there is
// one for this resonance, and STANDBY. open() leaves standby in RTP mode (MODE = 5).
//
// Envelope follower: the normalized drive is followed sample by sample (EnvelopeFollower) and every
// 1/update_rate_hz its envelope is written to RTP_INPUT, only when the code changes. Pulses shorter
// than the profile's min_pulse are stretched to it.
//
// Loop mapping: the chip drives closed loop at the LRA's tracked resonance; this is the mode for DOT
// (carrier at resonance) and LINE (ringing near f_N). When the drive's own carrier frequency (zero
// crossings) is more than open_loop_tolerance away from the resonance, as for SURFACE textures whose
// frequency v/lambda follows the finger, the driver switches to open loop (CONTROL3 LRA_OPEN_LOOP)
// and writes OL_LRA_PERIOD = 1 / (f * 98.46 us) as f changes. A caller that knows the content may
// force the mode with set_loop_hint().
//
// Clamp: in closed loop RTP full scale is RATED_VOLTAGE, so the top code is 255 (unsigned) / 127
// (signed). In open loop full scale is OD_CLAMP, so the top code is scaled by rated/clamp so that the
// steady drive never exceeds the rated voltage. No RTP write is ever above max_rtp_code().
//
// Faults (docs/hardware.md, "Faults and reconnection"): on the render thread NACK/EIO are retried
// with exponential backoff (waiting on the device); a write that still fails is dropped and
// reported once per episode; ENODEV, or failures_until_gone failed updates in a row, mean the
// device is gone: the driver posts device_gone, takes its DeviceLink down and skips output. The
// device service thread reconnects it (reconnect(): reopen + initialize) and puts the link up.
// STATUS is polled: over-current or over-temperature puts the chip in standby and stops output.
// rest_requested() (a signal) puts it to rest at the next write.
//
// Threads:
//   - control thread: construction, initialize(), calibrate(), open(), close(), destruction, while
//     neither the render thread nor the device service uses the driver;
//   - render thread: write(). It never throws, allocates, locks or reopens; it waits only on the
//     device (pacing, retry backoff) and uses the bus only while link() is up;
//   - device service thread: faults() (consumer), device_path(), reconnect() while link() is down;
//   - any thread: set_loop_hint(), device_gone().
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "storage/actuator_profile.hpp"
#include "realtime/clock.hpp"
#include "hal/update_schedule.hpp"
#include "storage/drv2605l_calibration_file.hpp"
#include "hal/envelope_follower.hpp"
#include "hal/fault_log.hpp"
#include "hal/transfer_retry.hpp"
#include "hal/gpio_output.hpp"
#include "hal/i2c_bus.hpp"
#include "hal/serviced_device.hpp"
#include "player/drive_sink.hpp"

namespace vimg {

struct Drv2605lOptions {
  double update_rate_hz = 2000.0;      // RTP writes per second at most (the bus allows ~13.8 k)
  bool signed_rtp = false;             // CONTROL3 bit 3 clear: signed data, codes 0..127
  double release_time_s = 0.010;       // envelope decay after the hold
  double open_loop_tolerance = 0.15;   // relative distance from resonance that selects open loop
  double status_poll_interval_s = 0.05;
  int max_retries = 3;                 // after the first attempt
  std::int64_t first_backoff_us = 100; // doubles each retry
  int failures_until_gone = 20;        // consecutive failed updates that mean the device is gone
  bool pace_writes = true;             // wait on the clock until each update's time within a block
  std::filesystem::path calibration_file;  // empty: none stored or restored
};

enum class LoopHint : std::uint8_t { automatic, closed_loop, open_loop };

class Drv2605lDriver final : public DriveSink, public ServicedDevice {
 public:
  // `enable_pin` may be null (EN tied high). The references must outlive the driver.
  Drv2605lDriver(I2cBus& bus, GpioOutput* enable_pin, Clock& clock, const ActuatorProfile& profile,
                 Drv2605lOptions options = {});
  ~Drv2605lDriver() override;  // rest, then EN low

  void initialize();                  // throws DeviceError with a clear message
  Drv2605lCalibration calibrate();    // auto-calibration; stores the result; throws on DIAG_RESULT

  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override;

  FaultLog& faults() override { return faults_; }
  const DeviceLink& link() const override { return link_; }
  const std::string& device_path() const override { return bus_.path(); }
  void reconnect() override;

  void set_loop_hint(LoopHint hint, double frequency_hz = 0.0);

  std::uint8_t max_rtp_code() const;  // for the current loop mode
  bool open_loop() const { return open_loop_; }
  bool output_stopped() const { return stopped_; }
  bool device_gone() const { return !link_.up(); }
  std::optional<std::string> calibration_warning() const { return calibration_warning_; }

 private:
  template <typename Attempt>
  int retry(Attempt&& attempt);                           // 0 or the errno of the last attempt
  void write_reg(std::uint8_t reg, std::uint8_t value);   // throws after retries
  std::uint8_t read_reg(std::uint8_t reg);                // throws after retries
  // Render thread: false when the transfer failed (reported) or the device is gone.
  bool rt_write_reg(std::uint8_t reg, std::uint8_t value) noexcept;
  bool rt_read_reg(std::uint8_t reg, std::uint8_t& value) noexcept;
  bool account(int error) noexcept;
  void update(std::int64_t time_us) noexcept;
  void resume(std::int64_t time_us) noexcept;
  void select_loop(bool open_loop, double frequency_hz) noexcept;
  void poll_status(std::int64_t time_us) noexcept;
  void stop_output(FaultKind why) noexcept;
  void enter_rest() noexcept;
  void apply_calibration(const Drv2605lCalibration& calibration);

  I2cBus& bus_;
  GpioOutput* enable_pin_;
  Clock& clock_;
  ActuatorProfile profile_;
  Drv2605lOptions options_;
  std::uint8_t address_;
  FaultLog faults_;
  DeviceLink link_;
  bool playing_ = false;  // control thread (open, close), read by the render thread

  // Device state: the chip's registers as we left them. Used by whichever thread holds the link.
  bool initialized_ = false;
  bool open_loop_ = false;
  std::uint8_t control3_ = 0;
  std::uint8_t last_period_code_ = 0;
  std::optional<std::string> calibration_warning_;

  // Render thread only (and the control thread in open()).
  EnvelopeFollower follower_;
  UpdateSchedule schedule_;
  TransferAccount transfer_;  // gone: the render thread took the link down and has not seen it up again
  bool stopped_ = false;
  bool rest_reported_ = false;
  std::uint8_t last_rtp_code_ = 0;
  std::uint8_t pulse_code_ = 0;
  std::int64_t pulse_start_us_ = 0;
  std::int64_t last_status_poll_us_ = 0;

  std::atomic<LoopHint> hint_{LoopHint::automatic};
  std::atomic<double> hint_frequency_hz_{0.0};
};

}  // namespace vimg
