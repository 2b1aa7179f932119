#pragma once
// ST-SIM, the spectral-temporal similarity of a distorted vibrotactile signal to a reference
// (Hassen and Steinbach, IEEE Transactions on Haptics 2020), computed as the reference
// implementation does (the `vibromaf` package, vibromaf/metrics/stsim.py; docs/stsim.md):
//   signals sampled at 8 kHz, cut into blocks of 512 samples (a last partial block is dropped);
//   spectral term: per block the orthonormal DCT-II in dB, 20 log10 |X_k|, minus the perceptual
//     threshold (vibrotactile_threshold.hpp), through the normal CDF with a 12 dB scale (the
//     "spectral support", in [0, 1]; a coefficient of exactly 0 has support 0);
//   temporal term: per block the samples normalised to zero mean and unit deviation,
//     (x - mean) / (std + eps), std the population deviation, eps the double epsilon (a silent or
//     constant block normalises to zeros);
//   both terms: sim(R, D) = mean over blocks of sum(R * D) / (sum(R^2) + eps), R the reference;
//   ST-SIM = temporal^eta * spectral^(1 - eta), eta = 2/3; signals equal sample for sample give 1
//   (checked before anything else, as the reference does); a negative temporal term gives 0
//   (where the reference's Python would return a complex number).
// Either term, and ST-SIM, may exceed 1 (each block is divided by the reference block's energy
// alone, plus an absolute eps): a little where the distorted block is louder, by up to
// sqrt(512 / eps) / 2 = 7.6e8 where the reference block is only a ring decayed far below threshold
// (docs/stsim.md, "Values far above 1"); the value is reported as computed, as the reference does.
//
// Analyse each signal once (analyse_stsim), then compare features as often as needed (stsim);
// comparing two analysed 20 s signals costs about two passes over their features.
//
// Threads: pure functions over caller-owned data; no allocation in stsim().
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "primitives/perception/perception_matrix.hpp"
#include "primitives/perception/perception_rate.hpp"

namespace vimg {

inline constexpr double kStSimSampleRateHz = 8000.0;
static_assert(kStSimSampleRateHz == kPerceptionRateHz, "ST-SIM is reported beside the cues, on the same signals");
inline constexpr std::size_t kStSimBlockSamples = 512;
inline constexpr double kStSimEta = 2.0 / 3.0;           // weight of the temporal term
inline constexpr double kStSimSupportScaleDb = 12.0;     // scale of the normal CDF

// What ST-SIM needs of one signal. Built only by analyse_stsim().
struct StSimFeatures {
  std::vector<double> signal;            // the samples as given (the identity test compares them)
  std::size_t blocks = 0;                // signal.size() / 512, rounded down
  std::vector<double> spectral_support;  // blocks * 512, block after block
  std::vector<double> normalized;        // blocks * 512, block after block
  std::vector<double> support_energy;    // per block: sum of spectral_support^2 (its term as reference)
  std::vector<double> normalized_energy; // per block: sum of normalized^2
};

// signal_8khz: samples at kStSimSampleRateHz (any length; fewer than 512 samples give no blocks).
StSimFeatures analyse_stsim(std::span<const double> signal_8khz);

struct StSimScore {
  double temporal = 1.0;  // sim of the normalised blocks
  double spectral = 1.0;  // sim of the spectral supports
  double value = 1.0;     // temporal^eta * spectral^(1 - eta), 0 when temporal < 0
};

// ST-SIM of `distorted` against `reference`, as the reference implementation computes it. A
// distorted signal longer than the reference is cut to the reference's length first. No value
// (where the reference raises an error) when the distorted signal is shorter than the reference,
// or when the signals differ and the reference is shorter than one block, or when eta is not
// inside (0, 1).
std::optional<StSimScore> stsim(const StSimFeatures& distorted, const StSimFeatures& reference,
                                double eta = kStSimEta);

// ST-SIM over the first min(length) samples of both (signals of different lengths, e.g. two WAV
// files): the same as stsim() with both cut to the shorter length. No value only when that common
// part is shorter than one block and the two differ in it.
std::optional<StSimScore> stsim_common_length(const StSimFeatures& distorted, const StSimFeatures& reference,
                                              double eta = kStSimEta);

// ST-SIM with the mean over a subset of blocks: block k counts when use_block[k] is non-zero (k
// below the blocks of both and below use_block.size()). No identity test, no cutting. No value when
// no block counts.
std::optional<StSimScore> stsim_over_blocks(const StSimFeatures& distorted, const StSimFeatures& reference,
                                            std::span<const std::uint8_t> use_block, double eta = kStSimEta);

// stsim[i][j] = ST-SIM of signal i against reference j over their common length
// (stsim_common_length), NaN where it has no value; 1 on the diagonal.
PerceptionMatrix stsim_matrix(std::span<const StSimFeatures> signals);

}  // namespace vimg
