#include "hal/drv2605l_driver.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <stdexcept>

#include "hal/device_error.hpp"
#include "hal/drv2605l_registers.hpp"
#include "hal/rest_on_exit.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

using namespace drv2605l;

namespace {
// A throwing transfer as an errno value, for the retry loop of initialization and calibration.
template <typename Transfer>
int error_of(Transfer&& transfer) {
  try {
    transfer();
    return 0;
  } catch (const DeviceError& error) {
    return error.error_number() != 0 ? error.error_number() : EIO;
  }
}
}  // namespace

Drv2605lDriver::Drv2605lDriver(I2cBus& bus, GpioOutput* enable_pin, Clock& clock, const ActuatorProfile& profile,
                               Drv2605lOptions options)
    : bus_(bus),
      enable_pin_(enable_pin),
      clock_(clock),
      profile_(profile),
      options_(std::move(options)),
      address_(profile.address >= 0 ? static_cast<std::uint8_t>(profile.address) : kDefaultAddress) {
  if (profile_.type != ActuatorType::lra) {
    throw std::invalid_argument("actuator profile '" + profile_.name + "': the DRV2605L driver drives an LRA");
  }
  if (!(options_.update_rate_hz > 0.0)) {
    throw std::invalid_argument("DRV2605L update rate must be above 0 Hz");
  }
}

Drv2605lDriver::~Drv2605lDriver() {
  close();
  if (enable_pin_ != nullptr) {
    try {
      enable_pin_->set(false);
    } catch (const DeviceError&) {
      // The pin is released anyway when its owner goes.
    }
  }
}

template <typename Attempt>
int Drv2605lDriver::retry(Attempt&& attempt) {
  return retry_transfer(clock_, options_.max_retries, options_.first_backoff_us, attempt);
}

void Drv2605lDriver::write_reg(std::uint8_t reg, std::uint8_t value) {
  if (const int error = retry([&] { return error_of([&] { write_register(bus_, address_, reg, value); }); })) {
    throw DeviceError(bus_.path(), "DRV2605L at " + hex_byte(address_) + ": write register " + hex_byte(reg), error);
  }
}

std::uint8_t Drv2605lDriver::read_reg(std::uint8_t reg) {
  std::uint8_t value = 0;
  if (const int error = retry([&] { return error_of([&] { value = read_register(bus_, address_, reg); }); })) {
    throw DeviceError(bus_.path(), "DRV2605L at " + hex_byte(address_) + ": read register " + hex_byte(reg), error);
  }
  return value;
}

bool Drv2605lDriver::rt_write_reg(std::uint8_t reg, std::uint8_t value) noexcept {
  if (transfer_.gone) return false;
  return account(retry([&] { return try_write_register(bus_, address_, reg, value); }));
}

bool Drv2605lDriver::rt_read_reg(std::uint8_t reg, std::uint8_t& value) noexcept {
  if (transfer_.gone) return false;
  return account(retry([&] { return try_read_register(bus_, address_, reg, value); }));
}

bool Drv2605lDriver::account(int error) noexcept {
  return transfer_.account(error, options_.failures_until_gone, faults_, link_, clock_);
}

void Drv2605lDriver::initialize() {
  initialized_ = false;
  if (enable_pin_ != nullptr) {
    enable_pin_->set(true);
    clock_.sleep_for_us(kEnableWait_us);
  }
  const std::uint8_t status = read_reg(kStatus);
  const unsigned device_id = status >> 5;
  if (device_id != kDeviceIdDrv2605l) {
    throw DeviceError(bus_.path(), "device at " + hex_byte(address_) + " reports id " + std::to_string(device_id) +
                                       " in STATUS[7:5], expected 7 (DRV2605L)",
                      0);
  }
  write_reg(kMode, kModeDevReset);
  bool reset_done = false;
  for (int poll = 0; poll < 100 && !reset_done; ++poll) {
    clock_.sleep_for_us(100);
    reset_done = (read_reg(kMode) & kModeDevReset) == 0;
  }
  if (!reset_done) {
    throw DeviceError(bus_.path(), "DRV2605L did not clear DEV_RESET within 10 ms", 0);
  }
  write_reg(kMode, kModeStandby);
  write_reg(kLibrarySel, kLibraryLra);
  write_reg(kRatedVoltage, rated_voltage_code(profile_.rated_voltage_V, profile_.resonance_hz));
  const double clamp_V = std::max(profile_.overdrive_clamp_V, profile_.rated_voltage_V);
  write_reg(kOdClamp, overdrive_clamp_code(clamp_V));
  const std::uint8_t brake_factor = profile_.braking ? 3 : 7;  // 7 disables braking
  write_reg(kFeedback, static_cast<std::uint8_t>(kFeedbackLra | (brake_factor << 4) | (1u << 2) | 2u));
  write_reg(kControl1, static_cast<std::uint8_t>(0x80u | drive_time_code(profile_.resonance_hz)));
  control3_ = read_reg(kControl3);
  control3_ = static_cast<std::uint8_t>(options_.signed_rtp ? (control3_ & ~kControl3UnsignedRtp)
                                                            : (control3_ | kControl3UnsignedRtp));
  control3_ = static_cast<std::uint8_t>(control3_ & ~kControl3LraOpenLoop);
  write_reg(kControl3, control3_);
  open_loop_ = false;
  last_period_code_ = open_loop_period_code(profile_.resonance_hz);
  write_reg(kOlLraPeriod, last_period_code_);

  calibration_warning_.reset();
  if (!options_.calibration_file.empty()) {
    const CalibrationLoadResult stored = load_calibration(options_.calibration_file);
    if (!stored.diagnostics.empty()) {
      calibration_warning_ = stored.error();
    } else if (stored.calibration) {
      if (std::fabs(stored.calibration->resonance_hz - profile_.resonance_hz) <= 0.01 * profile_.resonance_hz) {
        apply_calibration(*stored.calibration);
      } else {
        calibration_warning_ = options_.calibration_file.string() + ": warning: calibration was made for " +
                               std::to_string(stored.calibration->resonance_hz) + " Hz, the profile says " +
                               std::to_string(profile_.resonance_hz) + " Hz; run calibration again";
      }
    }
  }
  initialized_ = true;
}

void Drv2605lDriver::apply_calibration(const Drv2605lCalibration& calibration) {
  write_reg(kACalComp, calibration.a_cal_comp);
  write_reg(kACalBemf, calibration.a_cal_bemf);
  const std::uint8_t feedback = read_reg(kFeedback);
  write_reg(kFeedback, static_cast<std::uint8_t>((feedback & ~0x03u) | (calibration.bemf_gain & 0x03u)));
}

Drv2605lCalibration Drv2605lDriver::calibrate() {
  if (!initialized_) {
    initialize();
  }
  write_reg(kMode, kModeAutoCalibration);
  write_reg(kGo, 1);
  bool done = false;
  for (int poll = 0; poll < 300 && !done; ++poll) {  // up to 3 s; the longest AUTO_CAL_TIME is 1.2 s
    clock_.sleep_for_us(10'000);
    done = (read_reg(kGo) & 1u) == 0;
  }
  if (!done) {
    write_reg(kMode, kModeStandby);
    throw DeviceError(bus_.path(), "DRV2605L auto-calibration did not finish within 3 s (GO stayed set)", 0);
  }
  const std::uint8_t status = read_reg(kStatus);
  if ((status & kStatusDiagResult) != 0) {
    write_reg(kMode, kModeStandby);
    throw DeviceError(bus_.path(),
                      "DRV2605L auto-calibration failed (DIAG_RESULT = 1): check the LRA wiring and the "
                      "profile's rated voltage, overdrive clamp and resonance",
                      0);
  }
  Drv2605lCalibration result;
  result.resonance_hz = profile_.resonance_hz;
  result.a_cal_comp = read_reg(kACalComp);
  result.a_cal_bemf = read_reg(kACalBemf);
  result.bemf_gain = static_cast<std::uint8_t>(read_reg(kFeedback) & 0x03u);
  write_reg(kMode, playing_ ? kModeRtp : kModeStandby);
  if (!options_.calibration_file.empty()) {
    if (auto error = save_calibration(result, options_.calibration_file)) {
      throw std::runtime_error(*error);
    }
  }
  return result;
}

void Drv2605lDriver::open(double sample_rate_hz) {
  if (!(sample_rate_hz > 0.0)) {
    throw std::invalid_argument("DRV2605L: sample rate must be above 0 Hz");
  }
  if (!link_.up()) {
    bus_.reopen();
    initialize();
    link_.put_up();
  } else if (!initialized_) {
    initialize();
  }
  follower_.configure(sample_rate_hz, profile_.resonance_hz, options_.release_time_s);
  schedule_.start(sample_rate_hz, options_.update_rate_hz);
  stopped_ = false;
  transfer_.reset();
  rest_reported_ = false;
  pulse_code_ = 0;
  if (open_loop_) {
    select_loop(false, profile_.resonance_hz);
  }
  write_reg(kRtpInput, 0);
  last_rtp_code_ = 0;
  write_reg(kMode, kModeRtp);
  playing_ = true;
  last_status_poll_us_ = clock_.now_us();
}

void Drv2605lDriver::set_loop_hint(LoopHint hint, double frequency_hz) {
  hint_frequency_hz_.store(frequency_hz);
  hint_.store(hint);
}

std::uint8_t Drv2605lDriver::max_rtp_code() const {
  const double full_scale = options_.signed_rtp ? 127.0 : 255.0;
  if (!open_loop_ || profile_.overdrive_clamp_V <= 0.0) {
    return static_cast<std::uint8_t>(full_scale);
  }
  const double ratio = std::min(1.0, profile_.rated_voltage_V / profile_.overdrive_clamp_V);
  return static_cast<std::uint8_t>(std::floor(full_scale * ratio));
}

void Drv2605lDriver::write(std::span<const float> drive, double block_start_time_s) {
  if (!playing_) {
    return;
  }
  if (rest_requested()) {
    if (!rest_reported_) {
      rest_reported_ = true;
      stop_output(FaultKind::rest_requested);
    }
    return;
  }
  schedule_.feed(
      drive, block_start_time_s, clock_, [this](float x) { follower_.push(x); },
      [this](std::int64_t time_us) { update(time_us); });
}

void Drv2605lDriver::update(std::int64_t time_us) noexcept {
  if (stopped_) {
    return;
  }
  if (options_.pace_writes) {
    clock_.sleep_until_us(time_us);
  }
  if (transfer_.gone) {
    if (!link_.up()) {
      return;  // the service is reconnecting: output is skipped, the bus left alone
    }
    resume(time_us);
  }
  if (time_us - last_status_poll_us_ >= std::llround(options_.status_poll_interval_s * 1e6)) {
    poll_status(time_us);
    if (stopped_ || transfer_.gone) {
      return;
    }
  }
  const double level = follower_.envelope();
  if (level > 0.0) {
    const LoopHint hint = hint_.load(std::memory_order_relaxed);
    const double measured_hz = follower_.frequency_hz();
    const double hinted_hz = hint_frequency_hz_.load(std::memory_order_relaxed);
    bool want_open = false;
    double open_hz = measured_hz;
    if (hint == LoopHint::open_loop) {
      want_open = true;
      open_hz = hinted_hz > 0.0 ? hinted_hz : (measured_hz > 0.0 ? measured_hz : profile_.resonance_hz);
    } else if (hint == LoopHint::automatic) {
      want_open = measured_hz > 0.0 &&
                  std::fabs(measured_hz - profile_.resonance_hz) > options_.open_loop_tolerance * profile_.resonance_hz;
    }
    if (want_open != open_loop_) {
      select_loop(want_open, open_hz);
    } else if (open_loop_) {
      const std::uint8_t period = open_loop_period_code(open_hz);
      if (period != last_period_code_ && rt_write_reg(kOlLraPeriod, period)) {
        last_period_code_ = period;
      }
    }
    if (transfer_.gone) {
      return;  // lost just now: the loop mode is the service's from here on
    }
  }
  const std::uint8_t max_code = max_rtp_code();
  auto code = static_cast<std::uint8_t>(std::min<long>(std::lround(level * max_code), max_code));
  const auto min_pulse_us = std::llround(profile_.min_pulse_s * 1e6);
  if (code > 0 && last_rtp_code_ == 0 && pulse_code_ == 0) {
    pulse_start_us_ = time_us;  // a new pulse starts
  }
  if (time_us - pulse_start_us_ < min_pulse_us) {
    pulse_code_ = std::max(pulse_code_, code);
    code = std::max(code, std::min(pulse_code_, max_code));  // stretch a short pulse
  } else if (code == 0) {
    pulse_code_ = 0;
  }
  if (code != last_rtp_code_ && rt_write_reg(kRtpInput, code)) {
    last_rtp_code_ = code;
  }
}

void Drv2605lDriver::resume(std::int64_t time_us) noexcept {
  // reconnect() left the chip initialized, in RTP mode at 0.
  transfer_.reset();
  last_rtp_code_ = 0;
  pulse_code_ = 0;
  last_status_poll_us_ = time_us;
}

void Drv2605lDriver::select_loop(bool open_loop, double frequency_hz) noexcept {
  if (open_loop) {
    const double full_scale = options_.signed_rtp ? 127.0 : 255.0;
    const double ratio = profile_.overdrive_clamp_V > 0.0
                             ? std::min(1.0, profile_.rated_voltage_V / profile_.overdrive_clamp_V)
                             : 1.0;
    const auto open_max = static_cast<std::uint8_t>(std::floor(full_scale * ratio));
    if (last_rtp_code_ > open_max) {  // never above the open-loop clamp, not even for one write
      if (!rt_write_reg(kRtpInput, open_max)) return;
      last_rtp_code_ = open_max;
    }
    const std::uint8_t period = open_loop_period_code(frequency_hz);
    if (!rt_write_reg(kOlLraPeriod, period)) return;
    last_period_code_ = period;
  }
  const auto control3 = static_cast<std::uint8_t>(open_loop ? (control3_ | kControl3LraOpenLoop)
                                                             : (control3_ & ~kControl3LraOpenLoop));
  if (rt_write_reg(kControl3, control3)) {
    control3_ = control3;
    open_loop_ = open_loop;
  }
}

void Drv2605lDriver::poll_status(std::int64_t time_us) noexcept {
  last_status_poll_us_ = time_us;
  std::uint8_t status = 0;
  if (!rt_read_reg(kStatus, status)) {
    return;
  }
  if ((status & kStatusOverCurrent) != 0) {
    stop_output(FaultKind::over_current);
  } else if ((status & kStatusOverTemp) != 0) {
    stop_output(FaultKind::over_temperature);
  }
}

void Drv2605lDriver::stop_output(FaultKind why) noexcept {
  enter_rest();
  stopped_ = true;
  faults_.push({why, 0, clock_.now_us()});
}

void Drv2605lDriver::reconnect() {
  // Service thread, link down: the render thread leaves the bus and the device state alone.
  bus_.reopen();
  initialize();
  if (playing_) {
    write_reg(kRtpInput, 0);
    write_reg(kMode, kModeRtp);
  }
  link_.put_up();  // after the last transfer: the render thread resumes (resume())
}

void Drv2605lDriver::enter_rest() noexcept {
  if (!link_.up() || !initialized_) {
    return;  // gone: nothing reaches the chip (and the device state is the service's)
  }
  if (transfer_.gone) {
    resume(clock_.now_us());  // the service reconnected it since the last update
  }
  retry([&] { return try_write_register(bus_, address_, kRtpInput, 0); });
  retry([&] { return try_write_register(bus_, address_, kMode, kModeStandby); });
  last_rtp_code_ = 0;
}

void Drv2605lDriver::close() {
  if (!playing_) {
    return;
  }
  playing_ = false;
  enter_rest();
}

}  // namespace vimg
