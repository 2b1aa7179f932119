#pragma once
// A DRV2605L driver wired to its emulator on an emulated bus, on a fake clock.
#include <memory>

#include "storage/actuator_profile.hpp"
#include "realtime/clock.hpp"
#include "hal/drv2605l_driver.hpp"
#include "hal/drv2605l_emulator.hpp"
#include "hal/emulated_i2c_bus.hpp"

namespace vimg::test {

inline ActuatorProfile lra_profile() {
  ActuatorProfile profile;
  profile.name = "test-lra";
  profile.type = ActuatorType::lra;
  profile.resonance_hz = 175.0;
  profile.rated_voltage_V = 1.8;
  profile.overdrive_clamp_V = 2.5;
  profile.min_pulse_s = 0.0;
  profile.braking = true;
  profile.driver = DriverChip::drv2605l;
  profile.address = 0x5A;
  return profile;
}

struct Drv2605lRig {
  explicit Drv2605lRig(ActuatorProfile profile = lra_profile(), Drv2605lOptions options = {},
                       Drv2605lEmulatorOptions emulator_options = {})
      : clock(1'000'000), chip(clock, emulator_options) {
    bus.attach(0x5A, chip);
    driver = std::make_unique<Drv2605lDriver>(bus, emulator_options.enable_tied_high ? nullptr : &chip.enable_pin(),
                                              clock, profile, options);
  }
  FakeClock clock;
  EmulatedI2cBus bus;
  Drv2605lEmulator chip;
  std::unique_ptr<Drv2605lDriver> driver;
};

}  // namespace vimg::test
