// Why ST-SIM runs far above 1 against a resonant actuator's ring (docs/stsim.md, "Values far above
// 1"): both terms divide by the reference block's own energy plus eps, and the temporal term first
// normalises each block by its deviation plus eps; eps is absolute (2.2e-16), sized for signals of
// order 1. A ring that decays towards zero without reaching it leaves reference blocks whose energy
// is of the order of eps, and a block where the other signal is still there then divides a normal
// cross term by almost nothing. Each block's ratio is bounded by Cauchy-Schwarz:
// |sum(R D)| / (sum(R^2) + eps) <= |R| sqrt(512) / (|R|^2 + eps) <= sqrt(512 / eps) / 2 = 7.6e8,
// which is therefore also the bound of both terms and of ST-SIM. Exactly silent blocks give 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "primitives/perception/stsim.hpp"

namespace vimg {
namespace {

constexpr double kRateHz = 8000.0;
constexpr double kCarrierHz = 175.0;
// The envelope's time constant of the shipped LRA profile's resonator (175 Hz, Q 10):
// Q / (pi f) = 18.2 ms.
constexpr double kRingTauS = 10.0 / (std::numbers::pi * kCarrierHz);
const double kBlockBound = std::sqrt(static_cast<double>(kStSimBlockSamples) / std::numeric_limits<double>::epsilon()) / 2.0;

// Two seconds of a 175 Hz tone at half scale that stops being driven at `stop_s` and rings down
// exp(-t / tau) from there; below `floor` (relative to 0.5) the ring is cut to exact zeros.
std::vector<double> ring(double stop_s, double floor = 0.0) {
  std::vector<double> x(static_cast<std::size_t>(2.0 * kRateHz));
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRateHz;
    const double envelope = t < stop_s ? 1.0 : std::exp(-(t - stop_s) / kRingTauS);
    x[n] = envelope < floor ? 0.0 : 0.5 * envelope * std::sin(2.0 * std::numbers::pi * kCarrierHz * t);
  }
  return x;
}

// Both terms of block b alone.
StSimScore block_terms(const StSimFeatures& distorted, const StSimFeatures& reference, std::size_t b) {
  std::vector<std::uint8_t> use(reference.blocks, 0);
  use[b] = 1;
  return *stsim_over_blocks(distorted, reference, use);
}

// The reference's peak in block b: 0.5 until 0.25 s, the ring's envelope at the block's start after.
double reference_peak(std::size_t b) {
  const double start_s = static_cast<double>(b * kStSimBlockSamples) / kRateHz;
  return 0.5 * std::exp(-std::max(0.0, start_s - 0.25) / kRingTauS);
}

TEST(StSimRange, AgainstARingThatNeverReachesZeroBothTermsRunFarAboveOne) {
  const StSimFeatures felt = analyse_stsim(ring(10.0));  // driven throughout
  const StSimFeatures rung = analyse_stsim(ring(0.25));  // driven 0.25 s, then only its ring
  double largest_spectral = 0.0, largest_temporal = 0.0;
  for (std::size_t b = 0; b < rung.blocks; ++b) {
    SCOPED_TRACE(b);
    const StSimScore s = block_terms(felt, rung, b);
    const double peak = reference_peak(b);
    if (static_cast<double>((b + 1) * kStSimBlockSamples) / kRateHz <= 0.25) {  // driven throughout
      EXPECT_NEAR(s.spectral, 1.0, 1e-9);
      EXPECT_NEAR(s.temporal, 1.0, 1e-9);
    }
    // Spectral: the ring far below threshold keeps a support of 1e-5 and less, the tone 1.
    if (peak < 1e-6 && peak > 1e-8) {
      EXPECT_GT(s.spectral, 1e4);
    }
    // Temporal: the ring's deviation falls below eps, its normalised block below unit deviation.
    if (peak < 1e-19 && peak > 1e-24) {
      EXPECT_GT(s.temporal, 1e4);
    }
    EXPECT_LE(std::fabs(s.spectral), kBlockBound);
    EXPECT_LE(std::fabs(s.temporal), kBlockBound);
    largest_spectral = std::max(largest_spectral, s.spectral);
    largest_temporal = std::max(largest_temporal, std::fabs(s.temporal));
  }
  EXPECT_GT(largest_spectral, 5e5);         // 8.2e5, the block where the ring is at 8e-9
  EXPECT_GT(largest_temporal, kBlockBound / 4.0);  // 2.5e8: the bound is reached in practice
  const StSimScore whole = *stsim(felt, rung);
  EXPECT_GT(whole.spectral, 1e4);  // 2.8e4
  EXPECT_GT(whole.temporal, 1e6);  // 1.3e7
  EXPECT_GT(whole.value, 1e6);     // 1.7e6
  EXPECT_LE(whole.value, kBlockBound);
  std::printf("felt against the ring: ST-SIM %.3g (temporal %.3g, spectral %.3g); largest block: temporal %.3g, "
              "spectral %.3g; bound %.3g\n",
              whole.value, whole.temporal, whole.spectral, largest_temporal, largest_spectral, kBlockBound);
}

TEST(StSimRange, TheOtherDirectionAndExactSilenceStayAtOrBelowOne) {
  const StSimFeatures felt = analyse_stsim(ring(10.0));
  const StSimFeatures rung = analyse_stsim(ring(0.25));
  // The ring against the tone: the reference is felt everywhere, so no block divides by almost
  // nothing, and the value means what the metric means.
  const StSimScore reverse = *stsim(rung, felt);
  EXPECT_GT(reverse.value, 0.2);  // 0.29
  EXPECT_LT(reverse.value, 0.4);
  EXPECT_LE(reverse.spectral, 1.01);
  EXPECT_LE(reverse.temporal, 1.0);
  // The same ring cut to exact zeros 60 dB down (the ideal actuator's silence): a silent
  // reference block gives 0 / eps = 0, and no block of the pair exceeds 1 by more than rounding
  // and the half-felt block where the cut falls.
  const StSimFeatures cut = analyse_stsim(ring(0.25, 1e-3));
  const StSimScore silent = *stsim(felt, cut);
  EXPECT_LT(silent.value, 0.3);  // 0.18
  EXPECT_GT(silent.value, 0.1);
  for (std::size_t b = 0; b < cut.blocks; ++b) {
    const StSimScore s = block_terms(felt, cut, b);
    EXPECT_LE(s.spectral, 1.2) << b;
    EXPECT_LE(s.temporal, 1.0 + 1e-9) << b;
  }
  std::printf("ring against felt: %.3g; felt against the ring cut at -60 dB: %.3g\n", reverse.value, silent.value);
}

}  // namespace
}  // namespace vimg
