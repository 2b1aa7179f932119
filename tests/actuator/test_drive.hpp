#pragma once
// A drive for the tests of what follows the drive (the editor's scope, the player's equalizer):
// a 60 Hz and a 175 Hz sine summed, 0.5 and 0.4 in amplitude, and, when silent_every > 0, a
// third of every 3 * silent_every samples silent (drive stopping and starting again).
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace vimg::test {

inline std::vector<float> two_tone_drive(std::size_t n, double rate_hz, std::size_t silent_every = 0) {
  std::vector<float> d(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / rate_hz;
    const bool silent = silent_every > 0 && (i / silent_every) % 3 == 2;
    d[i] = silent ? 0.0f
                  : static_cast<float>(0.5 * std::sin(2 * std::numbers::pi * 60 * t) +
                                       0.4 * std::sin(2 * std::numbers::pi * 175 * t));
  }
  return d;
}

}  // namespace vimg::test
