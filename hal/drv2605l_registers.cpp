#include "hal/drv2605l_registers.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::drv2605l {

namespace {
std::uint8_t to_code(double value, double low, double high) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, low, high)));
}
}  // namespace

std::uint8_t rated_voltage_code(double rated_voltage_V, double resonance_hz) {
  const double shape = std::sqrt(std::max(1e-6, 1.0 - (4.0 * 300e-6 + 300e-6) * resonance_hz));
  return to_code(rated_voltage_V / (20.58e-3 * shape), 0.0, 255.0);
}

std::uint8_t overdrive_clamp_code(double overdrive_clamp_V) {
  return to_code(overdrive_clamp_V / 21.96e-3, 0.0, 255.0);
}

std::uint8_t open_loop_period_code(double frequency_hz) {
  if (!(frequency_hz > 0.0)) {
    return 127;
  }
  return to_code(1.0 / (frequency_hz * kOlLraPeriodUnit_s), 1.0, 127.0);
}

double open_loop_period_frequency_hz(std::uint8_t code) {
  return 1.0 / (std::max<int>(code & 0x7F, 1) * kOlLraPeriodUnit_s);
}

std::uint8_t drive_time_code(double resonance_hz) {
  const double half_period_ms = 500.0 / resonance_hz;
  return to_code((half_period_ms - 0.5) / 0.1, 0.0, 31.0);
}

}  // namespace vimg::drv2605l
