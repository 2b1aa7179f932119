#include "hal/drv2605l_emulator.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "hal/drv2605l_registers.hpp"

namespace vimg {

using namespace drv2605l;

void Drv2605lEmulator::EnablePin::set(bool high) {
  if (high && !chip_.enable_high_) {
    chip_.enable_rise_us_ = chip_.clock_.now_us();
    chip_.reset_registers();  // power-up state
  }
  chip_.enable_high_ = high;
}

Drv2605lEmulator::Drv2605lEmulator(Clock& clock, Drv2605lEmulatorOptions options)
    : clock_(clock), options_(options), enable_pin_(*this) {
  reset_registers();
  if (options_.enable_tied_high) {
    enable_high_ = true;
    enable_rise_us_ = -kEnableWait_us;
  }
}

void Drv2605lEmulator::reset_registers() {
  registers_.fill(0);
  registers_[kStatus] = kDeviceIdDrv2605l << 5;
  registers_[kMode] = kModeStandby;
  registers_[kLibrarySel] = 0x01;
  registers_[kRatedVoltage] = 0x3E;
  registers_[kOdClamp] = 0x8C;
  registers_[kACalComp] = 0x0C;
  registers_[kACalBemf] = 0x6C;
  registers_[kFeedback] = 0x36;
  registers_[kControl1] = 0x93;
  registers_[kControl2] = 0xF5;
  registers_[kControl3] = 0xA0;
  registers_[kControl4] = 0x20;
  registers_[kOlLraPeriod] = 0x33;
  latched_status_ = 0;
  diag_failed_ = false;
  calibration_done_us_ = -1;
}

bool Drv2605lEmulator::acknowledges() {
  if (!enable_high_) {
    violations_.push_back("transfer at " + std::to_string(clock_.now_us()) + " us while EN is low");
    return false;
  }
  const std::int64_t since_enable = clock_.now_us() - enable_rise_us_;
  if (since_enable < kEnableWait_us) {
    violations_.push_back("transfer " + std::to_string(since_enable) + " us after EN went high (needs " +
                          std::to_string(kEnableWait_us) + " us)");
    return false;
  }
  return true;
}

void Drv2605lEmulator::spend_bus_time(std::size_t bytes, bool repeated_start) {
  if (options_.bus_hz <= 0.0) {
    return;
  }
  // START + address byte + data bytes (8 bits + ACK each) + STOP.
  double bits = 9.0 * static_cast<double>(bytes + 1) + 2.0;
  if (repeated_start) {
    bits += 9.0 + 1.0;  // repeated START and the address again
  }
  bus_time_fraction_us_ += bits / options_.bus_hz * 1e6;
  const auto whole_us = static_cast<std::int64_t>(bus_time_fraction_us_);
  bus_time_fraction_us_ -= static_cast<double>(whole_us);
  clock_.sleep_for_us(whole_us);
}

void Drv2605lEmulator::advance_internal_state() {
  const std::int64_t now = clock_.now_us();
  if (reset_done_us_ >= 0 && now >= reset_done_us_) {
    reset_done_us_ = -1;
    reset_registers();
  }
  if (calibration_done_us_ >= 0 && now >= calibration_done_us_) {
    finish_calibration();
  }
}

void Drv2605lEmulator::finish_calibration() {
  calibration_done_us_ = -1;
  registers_[kGo] = 0;
  ++calibrations_;
  const bool lra_selected = (registers_[kFeedback] & kFeedbackLra) != 0;
  diag_failed_ = !options_.actuator_connected || !lra_selected || registers_[kRatedVoltage] == 0 ||
                 registers_[kOdClamp] == 0;
  if (diag_failed_) {
    return;
  }
  // Results depend on the actuator and on the drive settings, as on the chip.
  const double resonance = options_.actuator_resonance_hz;
  registers_[kACalComp] = static_cast<std::uint8_t>(std::lround(12.0 + resonance / 100.0));
  registers_[kACalBemf] = static_cast<std::uint8_t>(std::lround(80.0 + registers_[kRatedVoltage] / 8.0));
  registers_[kFeedback] = static_cast<std::uint8_t>((registers_[kFeedback] & ~0x03u) | 0x02u);
  registers_[kLraResonancePeriod] = static_cast<std::uint8_t>(std::lround(1.0 / (resonance * kOlLraPeriodUnit_s)));
}

void Drv2605lEmulator::write_register(std::uint8_t reg, std::uint8_t value) {
  traffic_.push_back({clock_.now_us(), true, reg, value});
  switch (reg) {
    case kStatus:
      return;  // read-only
    case kMode:
      if ((value & kModeDevReset) != 0) {
        ++resets_;
        registers_[kMode] = value;
        reset_done_us_ = clock_.now_us() + options_.reset_time_us;
        return;
      }
      registers_[kMode] = value;
      return;
    case kGo:
      if ((value & 1u) != 0 && (registers_[kMode] & 0x07u) == kModeAutoCalibration &&
          (registers_[kMode] & kModeStandby) == 0) {
        static constexpr std::int64_t kCalibrationTime_us[4] = {150'000, 250'000, 500'000, 1'000'000};
        registers_[kGo] = 1;
        calibration_done_us_ = clock_.now_us() + kCalibrationTime_us[(registers_[kControl4] >> 4) & 3u];
      } else {
        registers_[kGo] = 0;  // other modes: a trigger that completes at once here
      }
      return;
    default:
      registers_[reg] = value;
  }
}

std::uint8_t Drv2605lEmulator::read_register(std::uint8_t reg) {
  std::uint8_t value = peek(reg);
  if (reg == kStatus) {
    latched_status_ = 0;  // OC_DETECT and OVER_TEMP clear when read
  }
  traffic_.push_back({clock_.now_us(), false, reg, value});
  return value;
}

std::uint8_t Drv2605lEmulator::peek(std::uint8_t reg) {
  advance_internal_state();
  if (reg == kStatus) {
    return static_cast<std::uint8_t>((kDeviceIdDrv2605l << 5) | (diag_failed_ ? kStatusDiagResult : 0) |
                                     latched_status_);
  }
  return registers_[reg];
}

void Drv2605lEmulator::on_write(std::span<const std::uint8_t> bytes) {
  spend_bus_time(bytes.size(), false);
  advance_internal_state();
  if (bytes.empty()) {
    return;
  }
  std::uint8_t reg = bytes[0];
  for (std::size_t i = 1; i < bytes.size(); ++i) {
    write_register(reg++, bytes[i]);  // auto-increment
  }
}

void Drv2605lEmulator::on_write_read(std::span<const std::uint8_t> out, std::span<std::uint8_t> in) {
  spend_bus_time(out.size() + in.size(), true);
  advance_internal_state();
  std::uint8_t reg = out.empty() ? 0 : out[0];
  for (std::size_t i = 1; i < out.size(); ++i) {
    write_register(reg++, out[i]);
  }
  for (auto& byte : in) {
    byte = read_register(reg++);
  }
}

std::vector<RegisterAccess> Drv2605lEmulator::writes_to(std::uint8_t reg) const {
  std::vector<RegisterAccess> writes;
  for (const auto& access : traffic_) {
    if (access.write && access.reg == reg) {
      writes.push_back(access);
    }
  }
  return writes;
}

void Drv2605lEmulator::write_trace_csv(std::ostream& out) const {
  out << "time_s,op,register,value\n";
  char line[64];
  for (const auto& access : traffic_) {
    std::snprintf(line, sizeof line, "%.6f,%s,0x%02X,0x%02X\n", static_cast<double>(access.time_us) * 1e-6,
                  access.write ? "write" : "read", access.reg, access.value);
    out << line;
  }
}

}  // namespace vimg
