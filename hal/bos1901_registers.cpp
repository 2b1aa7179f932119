#include "hal/bos1901_registers.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::bos1901 {

int play_code_for_rate(double sample_rate_hz) {
  for (int code = 0; code < 8; ++code) {
    if (std::fabs(rate_for_play_code(code) - sample_rate_hz) < 0.5) {
      return code;
    }
  }
  return -1;
}

double rate_for_play_code(int code) { return 1'024'000.0 / static_cast<double>(1 << code); }

std::uint16_t sample_code(double normalized) {
  const long value = std::lround(std::clamp(normalized, -1.0, 1.0) * kSampleMax);
  return static_cast<std::uint16_t>(static_cast<std::uint16_t>(value) & 0xFFFu);
}

int sample_value(std::uint16_t code) {
  const int value = code & 0xFFF;
  return value >= 0x800 ? value - 0x1000 : value;
}

}  // namespace vimg::bos1901
