// The masking noise's generator (apps/vimg-player/study_noise.hpp).
#include "apps/vimg-player/study_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace vimg::player_app {
namespace {

double rms(const std::vector<float>& x) {
  double sum = 0;
  for (float v : x) sum += static_cast<double>(v) * v;
  return std::sqrt(sum / static_cast<double>(x.size()));
}

TEST(WhiteNoise, HasTheLevelAsRmsAndStaysWithinFullScale) {
  for (double level : {0.05, 0.2, 0.5}) {
    WhiteNoise noise(level);
    std::vector<float> samples(200000);
    noise.fill(samples);
    EXPECT_NEAR(rms(samples), level, level * 0.01) << level;
    for (float v : samples) ASSERT_LE(std::abs(v), level * std::sqrt(3.0) + 1e-6);
  }
}

TEST(WhiteNoise, ALevelAboveUniformFullScaleIsPlayedAtItNeverClipped) {
  WhiteNoise noise(1.0);
  EXPECT_NEAR(noise.amplitude(), 1.0, 1e-12);
  std::vector<float> samples(50000);
  noise.fill(samples);
  EXPECT_NEAR(rms(samples), WhiteNoise::kMaxRms, 0.01);
  EXPECT_EQ(WhiteNoise(-1.0).amplitude(), 0.0);
  EXPECT_EQ(WhiteNoise(NAN).amplitude(), 0.0);
}

// The same everywhere: the generator is Vigna's splitmix64 (prng.di.unimi.it/splitmix64.c), whose
// outputs are standardised; from state 0 they are 0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4,
// 0x06C45D188009454F, 0xF88BB8A8724C81EC. The default seed is the generator's increment, so the
// noise starts at that sequence's second output. A sample is a (2 u - 1), u the output's top 53
// bits over 2^53, a = level sqrt(3), rounded to float.
TEST(WhiteNoise, FirstSamplesAreSplitmix64sPublishedOutputs) {
  const double a = 0.3 * std::sqrt(3.0);
  const auto sample = [a](std::uint64_t z) { return static_cast<float>(a * (2.0 * static_cast<double>(z >> 11) * 0x1.0p-53 - 1.0)); };
  WhiteNoise noise(0.3);
  std::vector<float> x(3);
  noise.fill(x);
  EXPECT_EQ(x, (std::vector<float>{sample(0x6E789E6AA1B965F4ull), sample(0x06C45D188009454Full), sample(0xF88BB8A8724C81ECull)}));
  // Worked out by hand for the first: u = 0.43152799704850997, a (2u - 1) = -0.0711582 (float).
  EXPECT_EQ(x[0], -0.07115819305181503f);
  // A seed is the generator's state: seed 0 starts at the sequence's first output.
  WhiteNoise from_zero(0.3, 0);
  std::vector<float> y(2);
  from_zero.fill(y);
  EXPECT_EQ(y, (std::vector<float>{sample(0xE220A8397B1DCDAFull), sample(0x6E789E6AA1B965F4ull)}));
}

TEST(WhiteNoise, NeighbouringSamplesAreUncorrelated) {
  WhiteNoise noise(0.3);
  std::vector<float> x(100000);
  noise.fill(x);
  double c = 0, p = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    c += static_cast<double>(x[i]) * x[i - 1];
    p += static_cast<double>(x[i]) * x[i];
  }
  EXPECT_LT(std::abs(c / p), 0.02);
}

}  // namespace
}  // namespace vimg::player_app
