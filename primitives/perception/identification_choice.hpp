#pragma once
// Absolute identification of one image among the n of a set (docs/identification.md):
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
//   eta_ij   = prod_{c: d'_c,ij > 0} M_c(j | i; i) / M_c(i | i; j)       (1 on the diagonal)
//   p(j | i) = (1 - lapse) eta_ij / sum_k eta_ik + lapse / n    (Luce's similarity choice model)
//
// M_c(r | i; q) is r's cell along cue c, as the chance of i's observation on that cue (Gaussian,
// unit variance, at i's value): the interval around r bounded on each side by the nearest of
//   - q, the other image of the pair, at half their distance on c;
//   - every member m that differs from r most on c (one cue per pair, the first of equals), where
//     the boundary between r and m crosses the line through r along c: (s^2 + e^2) / 2s, with s
//     their d' on c and e on the other cues (s / 2 when they differ on c alone).
// Positions along a cue are read from its distances: m lies on the side of r's nearest bounder p
// when d'_c(p, m)^2 < d'_c(r, m)^2 + d'_c(r, p)^2 (its projection on the axis from r to p is
// positive), and i's observation sits at +-d'_c(i, r) on the same reading.
//
// What the rule is exact for, against the observer who picks the nearest image in independent
// Gaussian noise on each cue: every set whose members differ on one cue (its cells are that
// observer's: members between two take the observations, so that information along one cue levels
// off as the set grows; `Identification.AlongOneCueTheMatrixIsTheNearestChoiceObserversExactly`);
// two images that differ on one cue (p = Phi(-d'/2): one JND apart, felt alone, they are confused
// 32 % of the time, against 25 % in a two-interval trial, discrimination_choice.hpp); and every set
// that is a full grid over its cues, whose matrix is the product of the cues' own matrices, so that
// information adds over independent cues. Where it is not: a pair that differs on several cues
// near threshold, told apart better than that observer could (one JND on each of two cues: 17.8 %
// confused against 25.1 %; pinned by
// `Identification.APairThatDiffersOnTwoCuesIsToldApartBetterThanTheNearestChoiceObserver`), and
// with it sets along a diagonal of the cues. A member crowds another on one cue only, so that a
// member close on every cue is not counted once per cue as if the set were a grid
// (`Identification.TheMiddleOfThreeAlongADiagonalIsNotHandedToTheFarMember`).
// Cost: O(n^3) per set (n <= kMaxCompareInputs in `vimg compare`).
//
// Threads: pure functions over caller-owned data.
#include <array>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/perception_matrix.hpp"

namespace vimg {

inline constexpr double kDPrimePerJnd = 0.9538725524;  // sqrt(2) * Phi^-1(0.75)
// Reasoned from the published ranges (docs/identification.md says how): one-dimensional sets of 3 to
// 12 images transfer 1.5-1.7 bits at any spacing, three-dimensional ones 4.5-4.9 bits.
inline constexpr double kContextNoisePerDPrime = 0.09;

// The range of the set along each cue, JNDs (the largest distance of any pair on that cue).
std::array<double, kCueCount> cue_ranges_jnd(const CueMatrix& d);

// d'_c of one pair on each cue, in a set whose ranges are `ranges_jnd` (cue_ranges_jnd).
std::array<double, kCueCount> identification_d_primes(const CueDistances& d, const std::array<double, kCueCount>& ranges_jnd,
                                                      const DiscriminationConstants& k = {});

// d: square [presented][chosen]. Rows sum to 1; the lapse rate is clamped to [0, 1]; empty for an
// empty input. The temperature of the constants is not used (it belongs to discrimination).
PerceptionMatrix identification_confusion(const CueMatrix& d, const DiscriminationConstants& k = {});

}  // namespace vimg
