#include "apps/vimg-player/study_noise.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::player_app {

WhiteNoise::WhiteNoise(double level_rms, std::uint64_t seed)
    : random_(seed), amplitude_(std::sqrt(3.0) * std::clamp(std::isfinite(level_rms) ? level_rms : 0.0, 0.0, kMaxRms)) {}

void WhiteNoise::fill(std::span<float> samples) noexcept {
  for (float& sample : samples) {
    sample = static_cast<float>(amplitude_ * (2.0 * random_.unit() - 1.0));
  }
}

}  // namespace vimg::player_app
