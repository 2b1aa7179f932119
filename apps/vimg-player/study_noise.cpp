#include "apps/vimg-player/study_noise.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::player_app {

WhiteNoise::WhiteNoise(double level_rms, std::uint64_t seed)
    : state_(seed), amplitude_(std::sqrt(3.0) * std::clamp(std::isfinite(level_rms) ? level_rms : 0.0, 0.0, kMaxRms)) {}

void WhiteNoise::fill(std::span<float> samples) noexcept {
  for (float& sample : samples) {
    // splitmix64
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    const double unit = static_cast<double>(z >> 11) * 0x1.0p-53;  // [0, 1)
    sample = static_cast<float>(amplitude_ * (2.0 * unit - 1.0));
  }
}

}  // namespace vimg::player_app
