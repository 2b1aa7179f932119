#include "primitives/signal/transfer.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/signal/normalizer.hpp"

namespace vimg {
namespace {

// Signed step count in [-clamp, clamp] for a drive, rounded to the nearest step.
int rtp_steps(double drive, int clamp_code) {
  const int limit = std::clamp(clamp_code, 0, 127);
  const int steps = static_cast<int>(std::lround(hard_clamp(drive) * 127.0));
  return std::clamp(steps, -limit, limit);
}

}  // namespace

double VoltageTransfer::volts(double drive) const {
  const double limit = std::abs(clamp_voltage_V);
  return std::clamp(hard_clamp(drive) * rated_voltage_V, -limit, limit);
}

std::uint8_t rtp_code_signed(double drive, int clamp_code) {
  return static_cast<std::uint8_t>(rtp_steps(drive, clamp_code) & 0xFF);
}

std::uint8_t rtp_code_unsigned(double drive, int clamp_code) {
  return static_cast<std::uint8_t>(128 + rtp_steps(drive, clamp_code));
}

}  // namespace vimg
