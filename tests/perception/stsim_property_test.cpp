// ST-SIM's properties by design (docs/stsim.md): identical signals give 1, the temporal term
// ignores level, a negative temporal term gives 0, the DCT is the orthonormal DCT-II.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "primitives/perception/block_dct.hpp"
#include "primitives/perception/stsim.hpp"
#include "texture_signals.hpp"

namespace vimg {
namespace {

std::vector<double> scaled(std::vector<double> x, double gain) {
  for (double& v : x) v *= gain;
  return x;
}

TEST(StSimProperties, IdenticalSignalsGiveOne) {
  for (const auto& x : {test::surface_signal(3.0), test::dot_signal(3.0), test::silence(3.0), std::vector<double>{0.0, 1.0}}) {
    const StSimFeatures f = analyse_stsim(x);
    const auto score = stsim(f, f);
    ASSERT_TRUE(score.has_value());
    EXPECT_EQ(score->value, 1.0);
    EXPECT_EQ(score->temporal, 1.0);
    EXPECT_EQ(score->spectral, 1.0);
  }
}

TEST(StSimProperties, TemporalTermIgnoresLevelAndIsSymmetricOnActiveBlocks) {
  const auto a = test::partials_signal(2.0, {{0.5, 80.0}, {0.2, 160.0}});
  const auto b = test::partials_signal(2.0, {{0.5, 80.0}, {0.3, 170.0}});
  const StSimFeatures fa = analyse_stsim(a), fb = analyse_stsim(b);
  const double base = stsim(fa, fb)->temporal;
  for (double gain : {0.01, 0.3, 7.0}) {
    EXPECT_NEAR(stsim(analyse_stsim(scaled(a, gain)), fb)->temporal, base, 1e-12) << gain;
    EXPECT_NEAR(stsim(fa, analyse_stsim(scaled(b, gain)))->temporal, base, 1e-12) << gain;
  }
  // Normalised blocks all have energy N, so the temporal term is a mean correlation: symmetric.
  EXPECT_NEAR(stsim(fb, fa)->temporal, base, 1e-12);
  // A copy at another level is the same waveform: temporal 1, and ST-SIM near 1 where the whole
  // spectrum stays far above threshold (the spectral term saturates).
  const auto loud = analyse_stsim(scaled(a, 0.5));
  EXPECT_NEAR(stsim(loud, fa)->temporal, 1.0, 1e-12);
  EXPECT_GT(stsim(loud, fa)->value, 0.95);
}

TEST(StSimProperties, NegativeTemporalTermGivesZero) {
  const auto a = test::partials_signal(2.0, {{0.5, 100.0}});
  const StSimFeatures fa = analyse_stsim(a), inverted = analyse_stsim(scaled(a, -1.0));
  const auto score = stsim(inverted, fa);
  ASSERT_TRUE(score.has_value());
  EXPECT_NEAR(score->temporal, -1.0, 1e-12);
  EXPECT_EQ(score->value, 0.0);
}

TEST(StSimProperties, LengthsAsTheReferenceTreatsThem) {
  const auto a = test::partials_signal(1.0, {{0.5, 100.0}, {0.1, 300.0}});
  std::vector<double> longer = a;
  longer.insert(longer.end(), 700, 0.25);
  const StSimFeatures fa = analyse_stsim(a), fl = analyse_stsim(longer);
  EXPECT_EQ(fa.blocks, 8000u / 512u);  // the partial last block is dropped
  EXPECT_EQ(stsim(fl, fa)->value, 1.0);           // cut to the reference's length: equal
  EXPECT_FALSE(stsim(fa, fl).has_value());        // distorted shorter than reference
  EXPECT_EQ(stsim_common_length(fa, fl)->value, 1.0);
  EXPECT_FALSE(stsim(fa, fa, 0.0).has_value());   // eta outside (0, 1)
  EXPECT_FALSE(stsim(fa, fa, 1.0).has_value());
  const StSimFeatures short_a = analyse_stsim(std::vector<double>(100, 0.1));
  const StSimFeatures short_b = analyse_stsim(std::vector<double>(100, 0.2));
  EXPECT_FALSE(stsim(short_a, short_b).has_value());
  EXPECT_EQ(stsim(short_a, short_a)->value, 1.0);
}

TEST(StSimProperties, SilenceAgainstASignalGivesZero) {
  const StSimFeatures quiet = analyse_stsim(test::silence(1.0));
  const StSimFeatures loud = analyse_stsim(test::partials_signal(1.0, {{0.5, 200.0}}));
  EXPECT_EQ(stsim(quiet, loud)->value, 0.0);
  EXPECT_EQ(stsim(loud, quiet)->value, 0.0);
}

TEST(StSimProperties, OverAllBlocksEqualsThePlainMetric) {
  const StSimFeatures a = analyse_stsim(test::surface_signal(3.0));
  const StSimFeatures b = analyse_stsim(test::surface_signal(3.0, 0.8, 60.0));
  const std::vector<std::uint8_t> all(a.blocks, 1);
  const auto plain = stsim(a, b);
  const auto over = stsim_over_blocks(a, b, all);
  ASSERT_TRUE(plain && over);
  EXPECT_NEAR(over->value, plain->value, 1e-12);
  EXPECT_FALSE(stsim_over_blocks(a, b, std::vector<std::uint8_t>(a.blocks, 0)).has_value());
}

TEST(StSimProperties, DctIsTheOrthonormalDctII) {
  std::array<double, kStSimBlockSamples> block{};
  for (std::size_t n = 0; n < block.size(); ++n) {
    block[n] = std::sin(0.37 * static_cast<double>(n)) + 0.25 * std::cos(0.011 * static_cast<double>(n * n));
  }
  std::array<double, kStSimBlockSamples> fast{};
  detail::orthonormal_dct_512(block, fast);
  const long double pi = std::numbers::pi_v<long double>;
  const long double n_total = kStSimBlockSamples;
  for (std::size_t k = 0; k < block.size(); ++k) {
    long double sum = 0;
    for (std::size_t n = 0; n < block.size(); ++n) {
      sum += block[n] * std::cos(pi * static_cast<long double>(k) * (2.0L * static_cast<long double>(n) + 1.0L) / (2.0L * n_total));
    }
    const long double scale = k == 0 ? std::sqrt(1.0L / n_total) : std::sqrt(2.0L / n_total);
    EXPECT_NEAR(fast[k], static_cast<double>(scale * sum), 1e-12) << k;
  }
}

}  // namespace
}  // namespace vimg
