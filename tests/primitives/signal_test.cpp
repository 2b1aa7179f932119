#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "primitives/signal/normalizer.hpp"
#include "primitives/signal/transfer.hpp"

namespace vimg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Limiter, HardClampBoundsAndKeepsSmallValues) {
  EXPECT_EQ(hard_clamp(0.3), 0.3);
  EXPECT_EQ(hard_clamp(-7.0), -1.0);
  EXPECT_EQ(hard_clamp(kInf), 1.0);
  EXPECT_EQ(hard_clamp(kNaN), 0.0);
}

TEST(Limiter, SoftKneeIsLinearBelowTheKneeSmoothAndBoundedAbove) {
  for (const double knee : {0.0, 0.5, 0.8, 0.95}) {
    double previous = -1.0;
    for (double x = -5.0; x <= 5.0; x += 1e-3) {
      const double y = soft_limit(x, knee);
      EXPECT_LT(std::abs(y), 1.0 + 1e-15);
      EXPECT_GE(y, previous) << "monotonic";
      EXPECT_NEAR(soft_limit(-x, knee), -y, 1e-15) << "odd";
      if (std::abs(x) <= knee) {
        EXPECT_EQ(y, x);
      }
      // Slope never above 1: no point is amplified.
      EXPECT_LE(y - previous, 1e-3 + 1e-12);
      previous = y;
    }
    // Slope 1 just above the knee (no corner), saturating far above.
    EXPECT_NEAR((soft_limit(knee + 1e-6, knee) - knee) / 1e-6, 1.0, 1e-3);
    EXPECT_GT(soft_limit(20.0, knee), 0.999);
  }
  EXPECT_EQ(soft_limit(2.0, 1.0), 1.0);
  EXPECT_EQ(soft_limit(kNaN, 0.8), 0.0);
}

TEST(Normalizer, ProjectsOnTheAxisAndScalesByFullScale) {
  const Normalizer hard(NormalizerParams{{0, 0, 2}, 0.5, LimitMode::hard_clamp, 0.8});
  EXPECT_NEAR(hard.drive({1, 1, 0.2}), 0.4, 1e-12);  // axis normalized: 0.2 / 0.5
  EXPECT_NEAR(hard.raw_drive({0, 0, -2.0}), -4.0, 1e-12);
  EXPECT_EQ(hard.drive({0, 0, -2.0}), -1.0);
  const Normalizer soft(NormalizerParams{{1, 0, 0}, 1.0, LimitMode::soft_knee, 0.8});
  EXPECT_NEAR(soft.drive({0.5, 3, 3}), 0.5, 1e-12);
  EXPECT_GT(soft.drive({2.0, 0, 0}), 0.8);
  EXPECT_LT(soft.drive({2.0, 0, 0}), 1.0);
}

TEST(Transfer, VoltsScaleByRatingAndNeverExceedTheClamp) {
  const VoltageTransfer t{2.0, 1.5};
  EXPECT_NEAR(t.volts(0.5), 1.0, 1e-12);
  EXPECT_EQ(t.volts(1.0), 1.5);
  EXPECT_EQ(t.volts(-3.0), -1.5);
  EXPECT_EQ(t.volts(kNaN), 0.0);
}

int as_signed(std::uint8_t code) { return code < 128 ? code : code - 256; }

TEST(Transfer, RtpCodesSignedAndUnsigned) {
  EXPECT_EQ(rtp_code_signed(0.0), 0x00);
  EXPECT_EQ(rtp_code_signed(1.0), 0x7F);
  EXPECT_EQ(rtp_code_signed(-1.0), 0x81);  // -127 in two's complement
  EXPECT_EQ(rtp_code_signed(0.5), 64);     // 63.5 rounds away from zero
  EXPECT_EQ(rtp_code_unsigned(0.0), 128);
  EXPECT_EQ(rtp_code_unsigned(1.0), 255);
  EXPECT_EQ(rtp_code_unsigned(-1.0), 1);
  EXPECT_EQ(rtp_code_signed(1.0, 90), 90);
  EXPECT_EQ(as_signed(rtp_code_signed(-1.0, 90)), -90);
  EXPECT_EQ(rtp_code_unsigned(1.0, 90), 128 + 90);
  EXPECT_EQ(rtp_code_unsigned(kNaN), 128);
}

TEST(Transfer, PropertyCodesAreMonotonicAndNeverAboveTheClamp) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> drive(-3.0, 3.0);
  std::uniform_int_distribution<int> clamp(-10, 140);
  for (int i = 0; i < 20000; ++i) {
    const double a = drive(rng), b = drive(rng);
    const int c = clamp(rng);
    const int limit = std::min(std::max(c, 0), 127);
    const int sa = as_signed(rtp_code_signed(a, c)), sb = as_signed(rtp_code_signed(b, c));
    const int ua = rtp_code_unsigned(a, c) - 128, ub = rtp_code_unsigned(b, c) - 128;
    EXPECT_LE(std::abs(sa), limit);
    EXPECT_LE(std::abs(ua), limit);
    EXPECT_EQ(sa, ua) << "the two modes encode the same level";
    EXPECT_EQ(sb, ub);
    if (a <= b) {
      EXPECT_LE(sa, sb);
    } else {
      EXPECT_GE(sa, sb);
    }
    if (std::abs(a) <= 1.0 && std::abs(a * 127.0) < limit - 0.5) {
      EXPECT_LE(std::abs(sa - a * 127.0), 0.5 + 1e-9) << "nearest step";
    }
  }
}

}  // namespace
}  // namespace vimg
