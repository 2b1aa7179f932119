#pragma once
// The search behind `vimg study fit` (docs/studies.md, "Fitting the model"): the maximum of the
// likelihood over some free constants, the profile likelihood of one of them, and the choice of
// what a set of trials identifies. The choice sees only the trials it is given: leave one
// participant out runs it on the others' trials alone (study/fit_model.hpp).
//
//   - Candidates: the lapse rate, and the weight of each cue in which some pair of images of a set
//     with trials differs (a weight no pair exercises changes nothing; it keeps its default).
//   - Fit: Nelder-Mead (study/fit_nelder_mead.hpp) on the search coordinates, from the defaults.
//   - Profile: the smallest -ln L with one coordinate held, the others fitted again from the optimum.
//     Each side of a constant ends where the profile rises kProfileDrop95 above the optimum
//     (chi-square, 1 degree of freedom, 95 %; Venzon & Moolgavkar 1988), by bisection, or at the
//     box's edge when it stays below that.
//   - A constant whose profile stays within kProfileDrop95 over the whole box says nothing: it keeps
//     its default (a warning) and the rest are fitted again.
//   - A weight whose profile stays within kProfileDrop95 up to the box's upper edge is bounded from
//     below only ("at least"): the trials push it up as far as the context noise lets any weight
//     go. It is held at its default when the default is at least the profile's lower end, at that
//     end otherwise (the value nearest the published one that the trials allow; never the box's
//     edge, which no other set could be predicted with), and the rest are fitted again.
//
// Threads: pure; runs on the caller's thread.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "study/fit_likelihood.hpp"
#include "study/fit_nelder_mead.hpp"

namespace vimg::study {

inline constexpr double kProfileDrop95 = 1.9207294103470;  // chi2.ppf(0.95, 1) / 2

// The likelihood of some trials as a function of the free constants' search coordinates.
struct FitProblem {
  const std::vector<CueMatrix>* cues = nullptr;
  std::vector<ChoiceCounts> counts;
  DiscriminationConstants defaults;
  double nll(const std::vector<std::size_t>& free, std::span<const double> theta) const {
    return -log_likelihood(*cues, counts, constants_at(defaults, free, theta));
  }
};

struct Optimum {
  std::vector<double> theta;  // the coordinates of the free constants, in their order
  double nll = 0.0;
};

// The defaults' coordinates, and the optimum from `start`.
std::vector<double> default_start(const std::vector<std::size_t>& free, const DiscriminationConstants& defaults);
Optimum fit_constants(const FitProblem& p, const std::vector<std::size_t>& free, std::vector<double> start,
                      const NelderMeadOptions& options = {});

// The profile -ln L of coordinate m at x, the others fitted again from `hat`.
double profile_nll(const FitProblem& p, const std::vector<std::size_t>& free, std::size_t m, double x,
                   const std::vector<double>& hat);

struct ProfileSide {
  double theta = 0.0;    // where the profile has risen kProfileDrop95, or the box's edge
  bool at_edge = false;  // it did not rise that far before the edge
};

// The side of coordinate m's profile interval towards `edge` (theta_lower or theta_upper).
ProfileSide profile_side(const FitProblem& p, const std::vector<std::size_t>& free, std::size_t m, const Optimum& best,
                         double edge);

// The lapse rate, and each cue's weight when some pair of images of a set with trials differs in
// the cue; a warning for each cue left out.
std::vector<std::size_t> candidate_constants(const FitProblem& p, std::vector<std::string>& warnings);

struct FittedChoice {
  std::vector<std::size_t> free;          // identified: fitted, or held at a lower bound
  Optimum best;                           // the maximum over every constant of `free`
  std::vector<ProfileSide> lower, upper;  // each one's profile interval, in `free`'s order
  std::vector<bool> at_least;             // a weight the trials bound from below only
  DiscriminationConstants constants;      // the defaults, the identified constants set
  std::vector<std::string> warnings;      // what kept its default, and why
};

// Chooses what `p`'s trials identify and fits it, as the header says. `say` (may be null) hears a
// line of progress per step.
FittedChoice choose_and_fit(const FitProblem& p, void (*say)(const std::string& line));

}  // namespace vimg::study
