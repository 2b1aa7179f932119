#pragma once
// `vimg study fit`'s statistics (docs/studies.md, "Fitting the model"): the maximum-likelihood
// constants of the identification model on the trials (study/fit_likelihood.hpp), what the trials
// identify (study/fit_search.hpp), the 95 % intervals by a bootstrap over participants
// (study/fit_bootstrap.hpp) beside the profile-likelihood ones of the pooled trials, and
// leave-one-participant-out against a baseline.
//
//   - Stated interval: the bootstrap's percentiles. An end is open (a lapse rate of 0 or 0.5, a
//     weight of 0 or unbounded) when the bootstrap's percentile or the profile reaches the search
//     box's edge on that side: "at most" below, "at least" above.
//   - Baseline: the default constants with the lapse rate fitted on the same trials (the defaults
//     with a lapse rate of 0 lose to anything that allows a stray wrong answer).
//   - Leave one participant out: for each participant, everything chosen and fitted on the others
//     alone (which constants are free, which are held at a lower bound, the start: the defaults),
//     the baseline's lapse rate too; then the held-out participant's trials scored under the
//     constants so fitted, under the baseline, and under guessing. Nothing of the held-out
//     participant enters any choice.
//
// Threads: pure; runs on the caller's thread (progress is reported through a callback).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "study/fit_bootstrap.hpp"
#include "study/fit_likelihood.hpp"
#include "study/fit_search.hpp"

namespace vimg::study {

struct ConstantFit {
  std::string name;            // fit_constant_name(k), or "temperature_jnd"
  double value = 0.0;          // fitted (or held at a lower bound), or the default when not fitted
  double default_value = 0.0;
  bool fitted = false;         // identified by the trials
  bool at_least = false;       // a weight bounded from below only: held (fit_search.hpp)
  // The stated 95 % interval (bootstrap over participants); upper is +infinity when unbounded.
  double lower = 0.0, upper = 0.0;
  bool lower_open = false, upper_open = false;  // at the box's edge (by the bootstrap or the profile)
  // The 95 % profile-likelihood interval of the pooled trials (upper +infinity when unbounded).
  double profile_lower = 0.0, profile_upper = 0.0;
};

struct HeldOutParticipant {
  std::string participant;
  double trials = 0.0;
  DiscriminationConstants constants;  // chosen and fitted on the other participants alone
  double ll_fitted = 0.0;    // under `constants`
  double ll_baseline = 0.0;  // under the defaults with the lapse rate fitted on the others
  double ll_default = 0.0;   // under the defaults as they are
  double ll_chance = 0.0;    // guessing
};

struct ModelFit {
  DiscriminationConstants constants;  // the defaults with the identified constants set
  DiscriminationConstants defaults;
  DiscriminationConstants baseline;   // the defaults with the lapse rate fitted on all trials
  std::vector<ConstantFit> report;    // temperature, lapse rate, each cue's weight (in that order)
  std::size_t bootstrap_replicates = 0;
  double trials = 0.0;
  double ll_fitted = 0.0, ll_baseline = 0.0, ll_default = 0.0, ll_chance = 0.0;  // on all trials (in sample)
  std::vector<HeldOutParticipant> held_out;  // in the order of FitData::participants
  double held_out_ll_fitted = 0.0, held_out_ll_baseline = 0.0, held_out_ll_default = 0.0,
         held_out_ll_chance = 0.0;  // their sums
  std::vector<std::string> warnings;  // a constant kept at its default or held at a bound, and why
};

struct FitOptions {
  DiscriminationConstants defaults;
  BootstrapOptions bootstrap;
  // Called with a line of progress ("profile interval of lapse_rate (1 of 5)"); null: silent.
  void (*progress)(const std::string& line) = nullptr;
};

// Needs at least one trial; the caller refuses too little data first (fit_refusal).
ModelFit fit_identification_model(const FitData& data, const FitOptions& options);

// Why `data` cannot be fitted, or nothing: no trials, fewer than 2 participants (nobody to hold out),
// fewer than kMinTrialsPerFreeConstant trials per free constant.
inline constexpr double kMinTrialsPerFreeConstant = 10.0;
std::optional<std::string> fit_refusal(const FitData& data);

}  // namespace vimg::study
