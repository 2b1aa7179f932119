#pragma once
// The project's one seeded generator: Vigna's splitmix64 (Steele, Lea and Flood 2014;
// prng.di.unimi.it/splitmix64.c), whose outputs are standardised, so a seed gives the same draws on
// every platform, compiler and standard library (never std::*_distribution, whose output differs
// between libraries). From state 0 the first outputs are 0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4:
// tests/study_core/trial_plan_test.cpp and tests/player_app/study_noise_test.cpp pin them.
//
//   mix64(z)   the output function, a bijection of 64-bit words that mixes every bit into every bit
//   next()     state += kSplitMixGolden; return mix64(state)
//   unit()     the top 53 bits of next() over 2^53: uniform in [0, 1)
//   below(n)   uniform in [0, n), n > 0, without modulo bias (outputs under 2^64 mod n are drawn again)
//
// Users: the trial order (study/trial_plan.cpp), the masking noise (apps/vimg-player/study_noise.cpp),
// the test signals (tests/perception/fixture_signals.cpp, discrimination_model_test.cpp and
// bench/perception_bench.cpp's), the fit's simulated participants
// (tests/study_fit/fit_simulation.hpp) and its bootstrap (study/fit_bootstrap.cpp).
//
// Threads: a generator is a value; one per thread.
#include <cstdint>

namespace vimg {

inline constexpr std::uint64_t kSplitMixGolden = 0x9E3779B97F4A7C15ULL;  // 2^64 / golden ratio, odd

constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

class SplitMix64 {
 public:
  constexpr explicit SplitMix64(std::uint64_t seed) noexcept : state_(seed) {}
  constexpr std::uint64_t next() noexcept { return mix64(state_ += kSplitMixGolden); }
  constexpr double unit() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  constexpr std::uint64_t below(std::uint64_t n) noexcept {
    const std::uint64_t reject_below = (0 - n) % n;  // 2^64 mod n
    for (;;) {
      const std::uint64_t r = next();
      if (r >= reject_below) return r % n;
    }
  }

 private:
  std::uint64_t state_;
};

}  // namespace vimg
