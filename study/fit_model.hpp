#pragma once
// `vimg study fit`'s statistics (docs/studies.md, "Fitting the model"): the maximum-likelihood
// constants of the discrimination model on the trials (study/fit_likelihood.hpp), their 95 %
// profile-likelihood intervals, the constants the data cannot identify, and the
// leave-one-participant-out log-likelihood against the default constants.
//
//   - Free: the lapse rate and the weight of every cue that separates some pair of the sets with
//     trials (a weight no pair exercises keeps its default, with a warning). The temperature is
//     fixed at its default: only w_c / T enters the model, so the weights carry the scale.
//   - Fit: Nelder-Mead (study/fit_nelder_mead.hpp) on the search coordinates from the defaults.
//   - Interval: where the profile ln-likelihood (the others re-fitted) falls 1.92 below its maximum
//     (chi-square, 1 degree of freedom, 95 %; Venzon & Moolgavkar 1988), by bisection. A side that
//     stays within 1.92 up to the box's edge ends there: at the lower edge this says "at most" (a
//     lapse rate or a weight of zero is a real value); at the upper edge the data cannot identify
//     the constant, which then keeps its default (a warning names it) and the rest are fitted again.
//   - Leave one participant out: for each participant, the constants fitted (the same free set) on
//     everyone else, and the held-out participant's trials' ln-likelihood under them, under the
//     defaults and under guessing.
//
// Threads: pure; runs on the caller's thread (progress is reported through a callback).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "study/fit_likelihood.hpp"

namespace vimg::study {

inline constexpr double kProfileDrop95 = 1.9207294103470;  // chi2.ppf(0.95, 1) / 2

struct ConstantFit {
  std::string name;             // fit_constant_name(k), or "temperature_jnd"
  double value = 0.0;           // fitted, or the default when not fitted
  double default_value = 0.0;
  bool fitted = false;
  double lower = 0.0, upper = 0.0;  // the 95 % interval (fitted constants only)
  bool lower_at_edge = false;       // the interval runs to the search box's lower edge
};

struct HeldOutParticipant {
  std::string participant;
  double trials = 0.0;
  double ll_fitted = 0.0;   // under the constants fitted on the other participants
  double ll_default = 0.0;  // under the default constants
  double ll_chance = 0.0;   // guessing
};

struct ModelFit {
  DiscriminationConstants constants;  // the defaults with the fitted constants set
  DiscriminationConstants defaults;
  std::vector<ConstantFit> report;    // temperature, lapse rate, each cue's weight (in that order)
  double trials = 0.0;
  double ll_fitted = 0.0, ll_default = 0.0, ll_chance = 0.0;  // on all trials (in sample)
  std::vector<HeldOutParticipant> held_out;                  // in the order of FitData::participants
  double held_out_ll_fitted = 0.0, held_out_ll_default = 0.0, held_out_ll_chance = 0.0;  // their sums
  std::vector<std::string> warnings;  // a constant kept at its default, and why
};

struct FitOptions {
  DiscriminationConstants defaults;
  // Called with a line of progress ("profile interval of lapse_rate (1 of 5)"); null: silent.
  void (*progress)(const std::string& line) = nullptr;
};

// Needs at least one trial; the caller refuses too little data first (fit_refusal).
ModelFit fit_discrimination_model(const FitData& data, const FitOptions& options);

// Why `data` cannot be fitted, or nothing: no trials, fewer than 2 participants (nobody to hold out),
// fewer than kMinTrialsPerFreeConstant trials per free constant.
inline constexpr double kMinTrialsPerFreeConstant = 10.0;
std::optional<std::string> fit_refusal(const FitData& data);

}  // namespace vimg::study
