#include "primitives/perception/stsim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "primitives/perception/block_dct.hpp"
#include "primitives/perception/pairwise_sum.hpp"
#include "primitives/perception/vibrotactile_threshold.hpp"

namespace vimg {

namespace {

constexpr std::size_t kN = kStSimBlockSamples;
constexpr double kEps = std::numeric_limits<double>::epsilon();  // numpy.finfo(float).eps

// scipy.special.ndtr (Cephes): the standard normal CDF.
double normal_cdf(double a) {
  if (std::isnan(a)) return a;
  const double x = a * std::numbers::sqrt2 / 2.0;
  const double z = std::abs(x);
  if (z < std::numbers::sqrt2 / 2.0) return 0.5 + 0.5 * std::erf(x);
  const double y = 0.5 * std::erfc(z);
  return x > 0.0 ? 1.0 - y : y;
}

// The spectral support of one block: Phi((20 log10 |X_k| - T_k) / 12).
void block_support(std::span<const double, kN> block, std::span<double, kN> support) {
  std::array<double, kN> dct{};
  detail::orthonormal_dct_512(block, dct);
  const auto& threshold = stsim_threshold_db_per_bin();
  for (std::size_t k = 0; k < kN; ++k) {
    const double db = 2.0 * (10.0 * std::log10(std::abs(dct[k])));  // mag2db = 2 * pow2db
    support[k] = normal_cdf((db - threshold[k]) / kStSimSupportScaleDb);
  }
}

// (x - mean) / (std + eps), mean and population std in NumPy's summation order.
void block_normalize(std::span<const double, kN> block, std::span<double, kN> out) {
  const double n = static_cast<double>(kN);
  const double mean = detail::numpy_sum(kN, [&](std::size_t i) { return block[i]; }) / n;
  const double variance = detail::numpy_sum(kN, [&](std::size_t i) {
                            const double d = block[i] - mean;
                            return d * d;
                          }) / n;
  const double deviation = std::sqrt(variance) + kEps;
  for (std::size_t i = 0; i < kN; ++i) out[i] = (block[i] - mean) / deviation;
}

double block_energy(const std::vector<double>& values, std::size_t block) {
  const double* v = values.data() + block * kN;
  return detail::numpy_sum(kN, [&](std::size_t i) { return v[i] * v[i]; });
}

// sum(R * D) / (sum(R^2) + eps) for one block.
double block_sim(const std::vector<double>& reference, const std::vector<double>& reference_energy,
                 const std::vector<double>& distorted, std::size_t block) {
  const double* r = reference.data() + block * kN;
  const double* d = distorted.data() + block * kN;
  const double cross = detail::numpy_sum(kN, [&](std::size_t i) { return r[i] * d[i]; });
  return cross / (reference_energy[block] + kEps);
}

StSimScore combine(double temporal, double spectral, double eta) {
  StSimScore score;
  score.temporal = temporal;
  score.spectral = spectral;
  score.value = temporal < 0.0 ? 0.0 : std::pow(temporal, eta) * std::pow(spectral, 1.0 - eta);
  return score;
}

bool valid_eta(double eta) { return eta > 0.0 && eta < 1.0; }

bool equal_prefix(const StSimFeatures& a, const StSimFeatures& b, std::size_t samples) {
  return std::equal(a.signal.begin(), a.signal.begin() + static_cast<std::ptrdiff_t>(samples), b.signal.begin());
}

// ST-SIM over the first `blocks` blocks of both, means in NumPy's order.
StSimScore score_first_blocks(const StSimFeatures& distorted, const StSimFeatures& reference, std::size_t blocks,
                              double eta) {
  const double n = static_cast<double>(blocks);
  const double spectral = detail::numpy_sum(blocks, [&](std::size_t b) {
                            return block_sim(reference.spectral_support, reference.support_energy,
                                             distorted.spectral_support, b);
                          }) / n;
  const double temporal = detail::numpy_sum(blocks, [&](std::size_t b) {
                            return block_sim(reference.normalized, reference.normalized_energy,
                                             distorted.normalized, b);
                          }) / n;
  return combine(temporal, spectral, eta);
}

std::optional<StSimScore> compare(const StSimFeatures& distorted, const StSimFeatures& reference,
                                  std::size_t samples, double eta) {
  if (!valid_eta(eta)) return std::nullopt;
  if (equal_prefix(distorted, reference, samples)) return StSimScore{};
  const std::size_t blocks = samples / kN;
  if (blocks == 0) return std::nullopt;
  return score_first_blocks(distorted, reference, blocks, eta);
}

}  // namespace

StSimFeatures analyse_stsim(std::span<const double> signal_8khz) {
  StSimFeatures f;
  f.signal.assign(signal_8khz.begin(), signal_8khz.end());
  f.blocks = signal_8khz.size() / kN;
  f.spectral_support.resize(f.blocks * kN);
  f.normalized.resize(f.blocks * kN);
  f.support_energy.resize(f.blocks);
  f.normalized_energy.resize(f.blocks);
  for (std::size_t b = 0; b < f.blocks; ++b) {
    const std::span<const double, kN> block(signal_8khz.data() + b * kN, kN);
    block_support(block, std::span<double, kN>(f.spectral_support.data() + b * kN, kN));
    block_normalize(block, std::span<double, kN>(f.normalized.data() + b * kN, kN));
    f.support_energy[b] = block_energy(f.spectral_support, b);
    f.normalized_energy[b] = block_energy(f.normalized, b);
  }
  return f;
}

std::optional<StSimScore> stsim(const StSimFeatures& distorted, const StSimFeatures& reference, double eta) {
  if (distorted.signal.size() < reference.signal.size()) return std::nullopt;
  return compare(distorted, reference, reference.signal.size(), eta);
}

std::optional<StSimScore> stsim_common_length(const StSimFeatures& distorted, const StSimFeatures& reference,
                                              double eta) {
  return compare(distorted, reference, std::min(distorted.signal.size(), reference.signal.size()), eta);
}

std::optional<StSimScore> stsim_over_blocks(const StSimFeatures& distorted, const StSimFeatures& reference,
                                            std::span<const std::uint8_t> use_block, double eta) {
  if (!valid_eta(eta)) return std::nullopt;
  const std::size_t blocks = std::min({distorted.blocks, reference.blocks, use_block.size()});
  double spectral = 0.0;
  double temporal = 0.0;
  std::size_t counted = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    if (use_block[b] == 0) continue;
    spectral += block_sim(reference.spectral_support, reference.support_energy, distorted.spectral_support, b);
    temporal += block_sim(reference.normalized, reference.normalized_energy, distorted.normalized, b);
    ++counted;
  }
  if (counted == 0) return std::nullopt;
  const double n = static_cast<double>(counted);
  return combine(temporal / n, spectral / n, eta);
}

PerceptionMatrix stsim_matrix(std::span<const StSimFeatures> signals) {
  const std::size_t n = signals.size();
  PerceptionMatrix m(n, std::vector<double>(n, 1.0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      const auto score = stsim_common_length(signals[i], signals[j]);
      m[i][j] = score ? score->value : std::numeric_limits<double>::quiet_NaN();
    }
  }
  return m;
}

}  // namespace vimg
