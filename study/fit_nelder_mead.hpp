#pragma once
// Nelder and Mead's (1965) simplex minimiser within a box, for `vimg study fit` (study/fit_model.hpp):
// few parameters, a cheap objective, no derivatives. Deterministic: the same start gives the same
// result everywhere. Coordinates are clamped into [lower, upper] before the objective sees them.
// Standard coefficients (reflection 1, expansion 2, contraction 1/2, shrink 1/2); the search restarts
// from its best point with a fresh simplex until a restart improves the value by less than
// `tolerance` (a collapsed simplex is the method's known failure, McKinnon 1998).
//
// Threads: pure; the objective is called on the caller's thread.
#include <functional>
#include <span>
#include <vector>

namespace vimg::study {

struct NelderMeadOptions {
  double initial_step = 0.5;   // the first simplex: the start plus this along each axis (towards the box's inside)
  double tolerance = 1e-7;     // stop when the simplex's values span less than this
  int max_evaluations = 20000; // over all restarts
  int max_restarts = 4;
};

struct NelderMeadResult {
  std::vector<double> x;  // the best point found (within the box)
  double value = 0.0;     // the objective there
  int evaluations = 0;
};

using Objective = std::function<double(std::span<const double>)>;

// `start`, `lower` and `upper` have the same size (0 is allowed: the objective is evaluated once).
NelderMeadResult minimise_nelder_mead(const Objective& objective, std::vector<double> start, const std::vector<double>& lower,
                                      const std::vector<double>& upper, const NelderMeadOptions& options = {});

}  // namespace vimg::study
