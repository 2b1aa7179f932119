#include "primitives/perception/sensation_level.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "primitives/perception/block_dct.hpp"
#include "primitives/perception/stsim.hpp"
#include "primitives/perception/vibrotactile_threshold.hpp"

namespace vimg {

namespace {

constexpr std::size_t kN = kStSimBlockSamples;
constexpr std::size_t kHop = kN / 2;
constexpr double kBinHz = kStSimSampleRateHz / (2.0 * static_cast<double>(kN));  // 7.8125 Hz

// The band of DCT bin k, or kSensationBands when it belongs to none.
std::size_t band_of_bin(std::size_t k) {
  const double f = static_cast<double>(k) * kBinHz;
  for (std::size_t b = 0; b < kSensationBands; ++b) {
    if (f >= kSensationBandLowHz[b] && f < kSensationBandHighHz[b]) return b;
  }
  return kSensationBands;
}

double power_to_db(double power) {
  return power > 0.0 ? std::max(10.0 * std::log10(power), kSilentLevelDb) : kSilentLevelDb;
}

}  // namespace

double SensationLevels::felt_db(std::size_t band) const { return std::max(peak_level_db[band], 0.0); }

double SensationLevels::max_felt_db() const {
  double felt = 0.0;
  for (std::size_t b = 0; b < kSensationBands; ++b) felt = std::max(felt, felt_db(b));
  return felt;
}

double threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration) {
  const double above_best_db = vibrotactile_threshold_db(frequency_hz) - kThresholdAtBestFrequencyDb;
  return calibration.threshold_at_250hz_peak_displacement_m * std::pow(10.0, above_best_db / 20.0);
}

SensationLevels sensation_levels(std::span<const double> signal_8khz, const LevelCalibration& calibration) {
  // Per bin: its band and the weight (full-scale displacement / threshold)^2 * 2 / (N * 3/8), so
  // that a band's weighted power is the squared peak displacement, in threshold units, of a sine
  // carrying the same energy (3/8: the mean square of the Hann window). The DC bin is in no band.
  std::array<std::size_t, kN> band{};
  std::array<double, kN> weight{};
  for (std::size_t k = 0; k < kN; ++k) {
    band[k] = band_of_bin(k);
    if (band[k] == kSensationBands) continue;
    const double f = static_cast<double>(k) * kBinHz;
    const double omega = 2.0 * std::numbers::pi * f;
    const double displacement_m = calibration.full_scale_peak_acceleration_mps2 / (omega * omega);
    const double ratio = displacement_m / threshold_peak_displacement_m(f, calibration);
    weight[k] = ratio * ratio * 2.0 / (static_cast<double>(kN) * 3.0 / 8.0);
  }
  // Periodic Hann window: frames kHop apart add up to 1 everywhere.
  std::array<double, kN> window{};
  for (std::size_t n = 0; n < kN; ++n) {
    window[n] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(n) / static_cast<double>(kN));
  }

  SensationLevels levels;
  levels.peak_level_db.fill(kSilentLevelDb);
  const std::size_t size = signal_8khz.size();
  const std::size_t blocks = (size + kN - 1) / kN;
  levels.felt_block.assign(blocks, 0);
  std::array<double, kN> frame{};
  std::array<double, kN> dct{};
  // Frame j starts at j * kHop - kHop (the first one half before the signal), centre j * kHop.
  const std::size_t frames = (size + kHop - 1) / kHop + 1;
  for (std::size_t j = 0; j < frames && size > 0; ++j) {
    const std::ptrdiff_t start = static_cast<std::ptrdiff_t>(j * kHop) - static_cast<std::ptrdiff_t>(kHop);
    for (std::size_t n = 0; n < kN; ++n) {
      const std::ptrdiff_t i = start + static_cast<std::ptrdiff_t>(n);
      const bool inside = i >= 0 && static_cast<std::size_t>(i) < size;
      frame[n] = inside ? window[n] * signal_8khz[static_cast<std::size_t>(i)] : 0.0;
    }
    detail::orthonormal_dct_512(frame, dct);
    std::array<double, kSensationBands> power{};
    for (std::size_t k = 0; k < kN; ++k) {
      if (band[k] < kSensationBands) power[band[k]] += dct[k] * dct[k] * weight[k];
    }
    bool felt = false;
    for (std::size_t i = 0; i < kSensationBands; ++i) {
      const double db = power_to_db(power[i]);
      levels.peak_level_db[i] = std::max(levels.peak_level_db[i], db);
      felt = felt || db > 0.0;
    }
    if (!felt) continue;
    // Every block the frame overlaps, where the signal is not silent.
    const std::size_t first = start < 0 ? 0 : static_cast<std::size_t>(start) / kN;
    const std::size_t last = std::min((static_cast<std::size_t>(start + static_cast<std::ptrdiff_t>(kN)) - 1) / kN, blocks - 1);
    for (std::size_t b = first; b <= last; ++b) levels.felt_block[b] = 1;
  }
  for (std::size_t b = 0; b < blocks; ++b) {
    const auto begin = signal_8khz.begin() + static_cast<std::ptrdiff_t>(b * kN);
    const auto end = signal_8khz.begin() + static_cast<std::ptrdiff_t>(std::min(size, (b + 1) * kN));
    if (std::all_of(begin, end, [](double x) { return x == 0.0; })) levels.felt_block[b] = 0;
  }
  return levels;
}

}  // namespace vimg
