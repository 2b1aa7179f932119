#pragma once
// A DRV2605L driver wired to its emulator on an emulated bus, on a fake clock.
#include <memory>

#include "hal/output_spec.hpp"
#include "storage/actuator_profile.hpp"
#include "realtime/clock.hpp"
#include "hal/drv2605l_driver.hpp"
#include "hal/drv2605l_emulator.hpp"
#include "hal/emulated_i2c_bus.hpp"

namespace vimg::test {

// The shipped LRA (hal/output_spec.hpp's default_lra_profile, the one definition), without the
// pulse stretching, so that a test's pulses reach the chip as they are written.
inline ActuatorProfile lra_profile() {
  ActuatorProfile profile = default_lra_profile();
  profile.min_pulse_s = 0.0;
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
