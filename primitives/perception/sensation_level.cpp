#include "primitives/perception/sensation_level.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/perception/block_dct.hpp"
#include "primitives/perception/stsim.hpp"
#include "primitives/perception/vibrotactile_threshold.hpp"

namespace vimg {

namespace {

constexpr std::size_t kN = kStSimBlockSamples;
constexpr double kBinHz = kStSimSampleRateHz / (2.0 * static_cast<double>(kN));  // 7.8125 Hz

// The band of DCT bin k, or kSensationBands when it belongs to none.
std::size_t band_of_bin(std::size_t k) {
  const double f = static_cast<double>(k) * kBinHz;
  for (std::size_t b = 0; b < kSensationBands; ++b) {
    const double low = kSensationBandCentresHz[b] / std::sqrt(2.0);
    const double high = kSensationBandCentresHz[b] * std::sqrt(2.0);
    if (f >= low && f < high) return b;
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

double threshold_peak_acceleration_mps2(double frequency_hz, const LevelCalibration& calibration) {
  const double above_best_db = vibrotactile_threshold_db(frequency_hz) - kThresholdAtBestFrequencyDb;
  return calibration.threshold_at_250hz_peak_acceleration_mps2 * std::pow(10.0, above_best_db / 20.0);
}

SensationLevels sensation_levels(std::span<const double> signal_8khz, const LevelCalibration& calibration) {
  // Per bin: its band and the weight (full scale / threshold)^2 * 2 / N, so that a band's weighted
  // power is the squared peak amplitude, in threshold units, of a sine carrying the same energy.
  std::array<std::size_t, kN> band{};
  std::array<double, kN> weight{};
  for (std::size_t k = 0; k < kN; ++k) {
    band[k] = band_of_bin(k);
    const double ratio = calibration.full_scale_peak_acceleration_mps2 /
                         threshold_peak_acceleration_mps2(static_cast<double>(k) * kBinHz, calibration);
    weight[k] = ratio * ratio * 2.0 / static_cast<double>(kN);
  }

  SensationLevels levels;
  levels.peak_level_db.fill(kSilentLevelDb);
  const std::size_t blocks = (signal_8khz.size() + kN - 1) / kN;
  levels.felt_block.assign(blocks, 0);
  std::array<double, kN> block{};
  std::array<double, kN> dct{};
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t start = b * kN;
    const std::size_t count = std::min(kN, signal_8khz.size() - start);
    block.fill(0.0);
    std::copy_n(signal_8khz.begin() + static_cast<std::ptrdiff_t>(start), count, block.begin());
    detail::orthonormal_dct_512(block, dct);
    std::array<double, kSensationBands> power{};
    for (std::size_t k = 0; k < kN; ++k) {
      if (band[k] < kSensationBands) power[band[k]] += dct[k] * dct[k] * weight[k];
    }
    for (std::size_t i = 0; i < kSensationBands; ++i) {
      const double db = power_to_db(power[i]);
      levels.peak_level_db[i] = std::max(levels.peak_level_db[i], db);
      if (db > 0.0) levels.felt_block[b] = 1;
    }
  }
  return levels;
}

}  // namespace vimg
