#pragma once
// The likelihood that `vimg study fit` maximises (docs/studies.md, "Fitting the model"): each
// matching trial is one choice among its set's images, and the model gives it the probability
// p(chosen | presented) of identification_confusion over the set's cue distances
// (primitives/perception/identification_choice.hpp). Trials only enter through their counts per
// (presented, chosen) cell, so a likelihood costs one confusion matrix per set whatever the number
// of trials.
//
// The free constants are the lapse rate and the weight of each cue (the temperature belongs to
// two-interval discrimination and does not enter identification): the weights carry the scale. They are searched on unbounded-looking
// scales within wide boxes: the lapse rate as kMaxFittedLapse * logistic(theta), theta in
// [-12, 12]; a weight as w0 * exp(theta), theta in +-ln(1000), with w0 its default (1 when the
// default is 0).
//
// Threads: pure functions over caller-owned data.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/perception/identification_choice.hpp"
#include "primitives/perception/discrimination_cues.hpp"

namespace vimg::study {

// counts[presented][chosen] of one set, in the set's image order.
using ChoiceCounts = std::vector<std::vector<double>>;

// What a fit reads: the cue distances of every set's images as `vimg compare` renders them, and each
// participant's choice counts per set.
struct FitData {
  std::vector<std::string> set_names;
  std::vector<CueMatrix> set_cues;                // [set][i][j]
  std::vector<std::string> participants;          // sorted
  std::vector<std::vector<ChoiceCounts>> counts;  // [participant][set]
};

// The counts of every participant but `left_out` (every participant when it is out of range), per set.
std::vector<ChoiceCounts> pooled_counts(const FitData& data, std::size_t left_out = static_cast<std::size_t>(-1));
// The counts of the participants `chosen` (indices into FitData::participants; one drawn twice
// counts twice), per set: a bootstrap resample.
std::vector<ChoiceCounts> pooled_counts_of(const FitData& data, std::span<const std::size_t> chosen);
// The trials of one set, and of every set.
double set_trials(const ChoiceCounts& set);
double total_trials(const std::vector<ChoiceCounts>& counts);

// sum over sets and cells of count * ln p(chosen | presented); a cell whose p underflows counts as
// ln(1e-300).
double log_likelihood(const std::vector<CueMatrix>& set_cues, const std::vector<ChoiceCounts>& counts,
                      const DiscriminationConstants& constants);

// The ln-likelihood of guessing: every choice 1 / (images in the set).
double chance_log_likelihood(const std::vector<ChoiceCounts>& counts);

// ---- The free constants -----------------------------------------------------------------------

inline constexpr std::size_t kFitConstantCount = 1 + kCueCount;  // 0: the lapse rate; 1 + c: cue c's weight
inline constexpr double kMaxFittedLapse = 0.5;
inline constexpr double kLapseThetaBound = 12.0;
inline constexpr double kWeightThetaBound = 6.907755278982137;  // ln(1000)

// "lapse_rate", "cue_weight.<cue>" (the MODEL.json keys).
std::string fit_constant_name(std::size_t k);
double constant_value(const DiscriminationConstants& constants, std::size_t k);
void set_constant_value(DiscriminationConstants& constants, std::size_t k, double value);

// The search coordinate of constant k at `value` (clamped into its box), and back.
double to_theta(std::size_t k, double value, const DiscriminationConstants& defaults);
double from_theta(std::size_t k, double theta, const DiscriminationConstants& defaults);
double theta_lower(std::size_t k);
double theta_upper(std::size_t k);

// `defaults` with the constants `free` (indices k) set from the search coordinates `theta`.
DiscriminationConstants constants_at(const DiscriminationConstants& defaults, const std::vector<std::size_t>& free,
                                     std::span<const double> theta);

// True when some pair of different images of the sets lies apart in cue c (by more than 1e-9 JND):
// otherwise its weight cannot change the likelihood.
bool cue_separates_any_pair(const std::vector<CueMatrix>& set_cues, std::size_t cue);

}  // namespace vimg::study
