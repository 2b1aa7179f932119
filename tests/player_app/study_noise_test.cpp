// The masking noise's generator (apps/vimg-player/study_noise.hpp).
#include "apps/vimg-player/study_noise.hpp"

#include <gtest/gtest.h>

#include <cmath>
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

TEST(WhiteNoise, IsWhiteAndTheSameEverywhere) {
  WhiteNoise a(0.3), b(0.3);
  std::vector<float> x(100000), y(100000);
  a.fill(x);
  b.fill(y);
  EXPECT_EQ(x, y);
  // Neighbouring samples are uncorrelated.
  double c = 0, p = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    c += static_cast<double>(x[i]) * x[i - 1];
    p += static_cast<double>(x[i]) * x[i];
  }
  EXPECT_LT(std::abs(c / p), 0.02);
}

}  // namespace
}  // namespace vimg::player_app
