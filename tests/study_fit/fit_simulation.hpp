#pragma once
// Simulated participants for the fit's tests: choices drawn from a known identification model
// (p(j | i) of identification_confusion, written out again here from its equation) with a seeded
// generator that gives the same draws on every platform (the project's splitmix64,
// primitives/random/splitmix64.hpp; never std::*_distribution).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"
#include "primitives/random/splitmix64.hpp"

namespace vimg::fit_test {

using SplitMix = SplitMix64;  // primitives/random/splitmix64.hpp

// The model's choice probabilities of one presented image, from the equation of
// primitives/perception/identification_choice.hpp:
//   R_c = k w_c max_ab d_ab,c,  d'_c,ij = k w_c d_ij,c / sqrt(1 + (G R_c)^2),
//   eta_ij = prod_c Phi(-d'_c,ij/2) / Phi(d'_c,ij/2),  p(j|i) = (1 - lapse) eta_ij / sum_m eta_im + lapse / n,
// with k = sqrt(2) Phi^-1(0.75) and G the context noise, Phi through std::erf.
inline std::vector<double> choice_row(const CueMatrix& cues, std::size_t presented, const DiscriminationConstants& k) {
  const double per_jnd = std::sqrt(2.0) * 0.6744897501960817;  // Phi^-1(0.75)
  const double context = 0.09;
  const std::size_t n = cues.size();
  double range[kCueCount] = {};
  for (const auto& row : cues)
    for (const auto& d : row)
      for (std::size_t c = 0; c < kCueCount; ++c) range[c] = std::max(range[c], per_jnd * k.cue_weight[c] * d[c]);
  const auto phi = [](double x) { return 0.5 * (1.0 + std::erf(x / std::sqrt(2.0))); };
  std::vector<double> p(n);
  double total = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    p[j] = 1.0;
    for (std::size_t c = 0; c < kCueCount; ++c) {
      const double d = per_jnd * k.cue_weight[c] * cues[presented][j][c] / std::sqrt(1.0 + std::pow(context * range[c], 2));
      p[j] *= phi(-d / 2.0) / phi(d / 2.0);
    }
    total += p[j];
  }
  for (double& x : p) x = (1.0 - k.lapse_rate) * x / total + k.lapse_rate / static_cast<double>(n);
  return p;
}

// An image drawn from `row` (probabilities summing to 1).
inline std::size_t draw(const std::vector<double>& row, SplitMix& random) {
  const double u = random.unit();
  double cumulative = 0.0;
  for (std::size_t j = 0; j < row.size(); ++j) {
    cumulative += row[j];
    if (u < cumulative) return j;
  }
  return row.size() - 1;
}

}  // namespace vimg::fit_test
