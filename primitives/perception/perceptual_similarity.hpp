#pragma once
// Perceptual similarity of two vibrotactile signals, symmetric, in [0, 1] (docs/perception.md):
// ST-SIM for the structure (both directions), sensation level for what ST-SIM leaves out.
//   structure:  S = min(clamp(ST-SIM(a|b), 0, 1), clamp(ST-SIM(b|a), 0, 1)), ST-SIM taken over the blocks
//               where at least one of the two is felt (blocks silent to both carry nothing; the
//               plain ST-SIM counts them as dissimilar); 1 when the signals are equal or no block
//               is felt or the signals are shorter than one block;
//   visibility: v = min(1, max(felt a, felt b) / full_structure_db): structure counts fully once
//               one of them is felt well above threshold and fades as both near it;
//   level:      D = max over bands of |felt_a(band) - felt_b(band)| dB,
//               L = 2^(-D / level_halving_db);
//   similarity = (1 - v (1 - S)) * L.
// Two signals below threshold everywhere: v = 0, D = 0, similarity 1. Identical signals: 1.
//
// Threads: pure functions over caller-owned data.
#include <cstddef>
#include <span>
#include <vector>

#include "primitives/perception/perception_matrix.hpp"
#include "primitives/perception/sensation_level.hpp"
#include "primitives/perception/stsim.hpp"

namespace vimg {

// Everything the comparison needs of one signal; analyse each signal once.
struct PerceptualFeatures {
  StSimFeatures stsim;
  SensationLevels levels;
};

// signal_8khz: the predicted acceleration at the skin, normalised (|x| = 1 is full scale), 8 kHz.
PerceptualFeatures analyse(std::span<const double> signal_8khz, const LevelCalibration& calibration = {});

struct SimilarityConstants {
  double full_structure_db = 10.0;  // sensation level at which structure counts fully
  double level_halving_db = 20.0;   // a level difference that halves the similarity
};

struct PerceptualSimilarity {
  double stsim_ab = 1.0;             // ST-SIM of a against reference b over the felt blocks
  double stsim_ba = 1.0;             // ST-SIM of b against reference a over the felt blocks
  double structure = 1.0;            // S
  double visibility = 0.0;           // v
  double level_difference_db = 0.0;  // D
  double level = 1.0;                // L
  double value = 1.0;                // the similarity
};

PerceptualSimilarity perceptual_similarity(const PerceptualFeatures& a, const PerceptualFeatures& b,
                                           const SimilarityConstants& constants = {});

// similarity[i][j] = perceptual_similarity(i, j).value; symmetric, 1 on the diagonal.
PerceptionMatrix similarity_matrix(std::span<const PerceptualFeatures> signals,
                                   const SimilarityConstants& constants = {});

// stsim[i][j] = plain ST-SIM of signal i against reference j over their common length
// (stsim_common_length), NaN where it has no value; 1 on the diagonal.
PerceptionMatrix stsim_matrix(std::span<const PerceptualFeatures> signals);

}  // namespace vimg
