#pragma once
// Register-level emulator of a TI DRV2605L on an EmulatedI2cBus. It models the parts the driver
// depends on and records every access with its time, so that tests can assert the real traffic.
// Modelled: the register file with reset defaults, DEVICE_ID in STATUS[7:5], DEV_RESET (MODE bit 7)
// clearing itself after reset_time_us, STANDBY, GO clearing itself when auto-calibration ends (its
// duration from CONTROL4 AUTO_CAL_TIME) with DIAG_RESULT and A_CAL_COMP / A_CAL_BEMF / BEMF_GAIN
// results, STATUS OC_DETECT / OVER_TEMP latched until read, the EN pin and the 250 us wait after EN
// (an earlier transfer is not acknowledged and is recorded as a violation), and the bus time of each
// transfer (9 bits per byte plus START/STOP at bus_hz) on the shared clock.
#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "realtime/clock.hpp"
#include "hal/emulated_i2c_bus.hpp"
#include "hal/gpio_output.hpp"

namespace vimg {

struct Drv2605lEmulatorOptions {
  double actuator_resonance_hz = 175.0;  // what calibration finds
  bool actuator_connected = true;        // false: calibration fails (DIAG_RESULT = 1)
  bool enable_tied_high = false;         // true: no EN pin, enabled since time 0
  double bus_hz = 400'000.0;             // 0: transfers take no time
  std::int64_t reset_time_us = 100;
};

struct RegisterAccess {
  std::int64_t time_us = 0;
  bool write = false;
  std::uint8_t reg = 0;
  std::uint8_t value = 0;
};

class Drv2605lEmulator final : public I2cTarget {
 public:
  Drv2605lEmulator(Clock& clock, Drv2605lEmulatorOptions options = {});

  GpioOutput& enable_pin() { return enable_pin_; }

  bool acknowledges() override;
  void on_write(std::span<const std::uint8_t> bytes) override;
  void on_write_read(std::span<const std::uint8_t> out, std::span<std::uint8_t> in) override;

  // Raw register value as the chip holds it now (no side effects, not recorded).
  std::uint8_t peek(std::uint8_t reg);
  bool standby() { return (peek(0x01) & 0x40) != 0; }
  bool enabled() const { return enable_high_; }

  // Latches STATUS bits (e.g. OC_DETECT) as the chip would on a fault.
  void raise_status(std::uint8_t bits) { latched_status_ |= bits; }

  const std::vector<RegisterAccess>& traffic() const { return traffic_; }
  // Room for `accesses` more recorded accesses, so that recording allocates nothing meanwhile
  // (tests that count the driver's allocations).
  void reserve_traffic(std::size_t accesses) { traffic_.reserve(traffic_.size() + accesses); }
  std::vector<RegisterAccess> writes_to(std::uint8_t reg) const;
  const std::vector<std::string>& violations() const { return violations_; }
  std::int64_t enable_rise_time_us() const { return enable_rise_us_; }
  int resets() const { return resets_; }
  int calibrations() const { return calibrations_; }

  // time_s,op,register,value (hex), one row per register access.
  void write_trace_csv(std::ostream& out) const;

 private:
  class EnablePin final : public GpioOutput {
   public:
    explicit EnablePin(Drv2605lEmulator& chip) : chip_(chip) {}
    void set(bool high) override;
    const std::string& name() const override { return name_; }

   private:
    Drv2605lEmulator& chip_;
    std::string name_ = "drv2605l-emulated-en";
  };

  void reset_registers();
  void advance_internal_state();
  void write_register(std::uint8_t reg, std::uint8_t value);
  std::uint8_t read_register(std::uint8_t reg);
  void spend_bus_time(std::size_t bytes, bool repeated_start);
  void finish_calibration();

  Clock& clock_;
  Drv2605lEmulatorOptions options_;
  EnablePin enable_pin_;
  std::array<std::uint8_t, 256> registers_{};
  bool enable_high_ = false;
  std::int64_t enable_rise_us_ = 0;
  std::uint8_t latched_status_ = 0;
  bool diag_failed_ = false;
  std::int64_t reset_done_us_ = -1;
  std::int64_t calibration_done_us_ = -1;
  double bus_time_fraction_us_ = 0.0;
  std::vector<RegisterAccess> traffic_;
  std::vector<std::string> violations_;
  int resets_ = 0;
  int calibrations_ = 0;
};

}  // namespace vimg
