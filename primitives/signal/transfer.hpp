#pragma once
// Transfer functions f_T: normalized drive in [-1, 1] -> an actuator's input. Inputs outside
// [-1, 1] are clamped first, and NaN is treated as 0, so no output ever exceeds its clamp.
#include <cstdint>

namespace vimg {

struct VoltageTransfer {
  double rated_voltage_V = 2.0;  // drive 1 -> rated voltage
  double clamp_voltage_V = 2.0;  // never exceeded, whatever the drive or the rating

  double volts(double drive) const;
};

// DRV2605L real-time playback codes. The full scale is 127 steps either side of zero, and the
// magnitude never exceeds clamp_code (itself limited to 0..127).
// Signed mode (CONTROL3 bit 3 = 0): -127..127 as a two's-complement byte.
std::uint8_t rtp_code_signed(double drive, int clamp_code = 127);
// Unsigned mode (CONTROL3 bit 3 = 1): 0..255 with 128 = zero.
std::uint8_t rtp_code_unsigned(double drive, int clamp_code = 127);

}  // namespace vimg
