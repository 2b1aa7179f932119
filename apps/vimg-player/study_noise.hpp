#pragma once
// White noise for masking the actuator's sound during the matching test (the paper played white
// noise to every participant). Uniform samples in [-a, a] with a = level * sqrt(3), so that the RMS
// is `level` (linear, full scale 1); a uniform noise reaches full scale at RMS 1/sqrt(3) = 0.577, so
// a higher level is played at that RMS, never clipped. The project's own generator (splitmix64), so
// the noise is the same everywhere. Pure and allocation-free: it runs in the audio callback.
#include <cstdint>
#include <span>

#include "primitives/random/splitmix64.hpp"

namespace vimg::player_app {

class WhiteNoise {
 public:
  static constexpr double kMaxRms = 0.57735026918962576;  // 1 / sqrt(3)

  explicit WhiteNoise(double level_rms, std::uint64_t seed = kSplitMixGolden);
  void fill(std::span<float> samples) noexcept;
  double amplitude() const { return amplitude_; }  // a: samples lie in [-a, a]

 private:
  SplitMix64 random_;  // primitives/random/splitmix64.hpp
  double amplitude_;
};

}  // namespace vimg::player_app
