#include "primitives/perception/perceptual_similarity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vimg {

namespace {

double clamp01(double x) { return std::isnan(x) ? 0.0 : std::clamp(x, 0.0, 1.0); }

bool same_signal(const PerceptualFeatures& a, const PerceptualFeatures& b) {
  return a.stsim.signal == b.stsim.signal;
}

}  // namespace

PerceptualFeatures analyse(std::span<const double> signal_8khz, const LevelCalibration& calibration) {
  PerceptualFeatures features;
  features.stsim = analyse_stsim(signal_8khz);
  features.levels = sensation_levels(signal_8khz, calibration);
  return features;
}

PerceptualSimilarity perceptual_similarity(const PerceptualFeatures& a, const PerceptualFeatures& b,
                                           const SimilarityConstants& constants) {
  PerceptualSimilarity s;
  if (same_signal(a, b)) {
    s.visibility = std::min(1.0, a.levels.max_felt_db() / constants.full_structure_db);
    return s;
  }

  // Structure over the blocks that at least one of the two makes felt.
  const std::size_t blocks = std::min(a.stsim.blocks, b.stsim.blocks);
  std::vector<std::uint8_t> felt(blocks, 0);
  for (std::size_t k = 0; k < blocks; ++k) {
    const bool felt_a = k < a.levels.felt_block.size() && a.levels.felt_block[k] != 0;
    const bool felt_b = k < b.levels.felt_block.size() && b.levels.felt_block[k] != 0;
    felt[k] = (felt_a || felt_b) ? 1 : 0;
  }
  const auto ab = stsim_over_blocks(a.stsim, b.stsim, felt);
  const auto ba = stsim_over_blocks(b.stsim, a.stsim, felt);
  if (ab && ba) {
    s.stsim_ab = ab->value;
    s.stsim_ba = ba->value;
    // Each direction bounded, then the smaller: ST-SIM's spectral term divides by the reference's
    // support, so against a block that is only a decayed ring (an LRA never returns to exact zero)
    // one direction runs to 1e4 and more; the pair is alike only when each reproduces the other.
    s.structure = std::min(clamp01(s.stsim_ab), clamp01(s.stsim_ba));
  }

  const double felt_max = std::max(a.levels.max_felt_db(), b.levels.max_felt_db());
  s.visibility = std::min(1.0, felt_max / constants.full_structure_db);

  double difference = 0.0;
  for (std::size_t band = 0; band < kSensationBands; ++band) {
    difference = std::max(difference, std::abs(a.levels.felt_db(band) - b.levels.felt_db(band)));
  }
  s.level_difference_db = difference;
  s.level = std::exp2(-difference / constants.level_halving_db);
  s.value = clamp01((1.0 - s.visibility * (1.0 - s.structure)) * s.level);
  return s;
}

PerceptionMatrix similarity_matrix(std::span<const PerceptualFeatures> signals, const SimilarityConstants& constants) {
  const std::size_t n = signals.size();
  PerceptionMatrix m(n, std::vector<double>(n, 1.0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      m[i][j] = m[j][i] = perceptual_similarity(signals[i], signals[j], constants).value;
    }
  }
  return m;
}

PerceptionMatrix stsim_matrix(std::span<const PerceptualFeatures> signals) {
  const std::size_t n = signals.size();
  PerceptionMatrix m(n, std::vector<double>(n, 1.0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j) continue;
      const auto score = stsim_common_length(signals[i].stsim, signals[j].stsim);
      m[i][j] = score ? score->value : std::numeric_limits<double>::quiet_NaN();
    }
  }
  return m;
}

}  // namespace vimg
