#pragma once
// Absolute identification of one image among the n of a set (docs/perception.md, "Identification"):
// what the matching test asks of people and what `vimg compare` and `vimg separate` predict. The
// cues of each pair (discrimination_cues.hpp, in JNDs) are the same as for discrimination; what
// differs is the noise: besides the sensory noise that sets the JND, remembering where an image
// sits along a cue adds a context noise that grows with the range the set covers along that cue
// (Durlach & Braida 1969; Braida & Durlach 1972). So information along one cue saturates (people
// identify one-dimensional vibrotactile sets at 1-2 bits however far apart: Rabinowitz, Houtsma,
// Durlach & Delhorne 1987), while independent cues add (three-dimensional sets, 4-5 bits).
//
//   d'_c,ij  = k w_c d_c,ij / sqrt(1 + (G R_c)^2)      one cue, in units of the sensory noise
//              k = sqrt(2) z(0.75) = 0.954: one JND (75 % correct in two intervals) as d'
//              R_c = k w_c max_ab d_c,ab: the set's range along the cue, as d'
//              G = kContextNoisePerDPrime: context noise per unit of range
//   d'_ij    = sqrt(sum_c d'_c,ij^2)                       independent cues
//   eta_ij   = Phi(-d'_ij / 2) / Phi(d'_ij / 2)            pairwise confusability (eta_ii = 1)
//   p(j | i) = (1 - lapse) eta_ij / sum_k eta_ik + lapse / n    (Luce's similarity choice model)
//
// For two images the choice is exactly that of an observer who picks the nearer of the two in
// Gaussian noise: p = Phi(-d'/2), so images one JND apart are confused 32 % of the time when each
// is felt alone (against 25 % in a two-interval trial: discrimination_choice.hpp). For more images
// it is Luce's approximation of that observer.
//
// Threads: pure functions over caller-owned data.
#include <array>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/perception_matrix.hpp"

namespace vimg {

inline constexpr double kDPrimePerJnd = 0.9538725524;  // sqrt(2) * Phi^-1(0.75)
// Reasoned from the published ranges (docs/perception.md says how): one-dimensional sets of 3 to
// 12 images transfer 1.3-1.8 bits at any spacing, three-dimensional ones 4-5 bits.
inline constexpr double kContextNoisePerDPrime = 0.08;

// The range of the set along each cue, JNDs (the largest distance of any pair on that cue).
std::array<double, kCueCount> cue_ranges_jnd(const CueMatrix& d);

// d'_ij of one pair of a set whose ranges are `ranges_jnd` (cue_ranges_jnd).
double identification_d_prime(const CueDistances& d, const std::array<double, kCueCount>& ranges_jnd,
                              const DiscriminationConstants& k = {});

// d: square [presented][chosen]. Rows sum to 1; the lapse rate is clamped to [0, 1]; empty for an
// empty input. The temperature of the constants is not used (it belongs to discrimination).
PerceptionMatrix identification_confusion(const CueMatrix& d, const DiscriminationConstants& k = {});

}  // namespace vimg
