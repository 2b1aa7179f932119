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
// primitives/perception/identification_choice.hpp, written out again here:
//   R_c = k w_c max_ab d_ab,c,  d'_c,ij = k w_c d_ij,c / sqrt(1 + (G R_c)^2),
//   eta_ij = prod_{c: d'_c,ij > 0} M_c(j | i, partner i) / M_c(i | i, partner j),
//   p(j|i) = (1 - lapse) eta_ij / sum_m eta_im + lapse / n,
// M_c(r | i, partner): r's cell on cue c, bounded on each side by the nearest of the partner (at
// d'/2) and the members that differ from r most on c (at (s^2 + e^2) / 2s), as the chance of
// i's observation, Phi through std::erf. Sides: k is on the side of r's nearest bounder q when
// d'_c(q, k)^2 < d'_c(r, k)^2 + d'_c(r, q)^2.
inline std::vector<double> choice_row(const CueMatrix& cues, std::size_t presented, const DiscriminationConstants& k) {
  const double per_jnd = std::sqrt(2.0) * 0.6744897501960817;  // Phi^-1(0.75)
  const double context = 0.09;
  const std::size_t n = cues.size();
  double range[kCueCount] = {};
  for (const auto& row : cues)
    for (const auto& d : row)
      for (std::size_t c = 0; c < kCueCount; ++c) range[c] = std::max(range[c], per_jnd * k.cue_weight[c] * d[c]);
  const auto dp = [&](std::size_t a, std::size_t b, std::size_t c) {
    return per_jnd * k.cue_weight[c] * cues[a][b][c] / std::sqrt(1.0 + std::pow(context * range[c], 2));
  };
  const auto phi = [](double x) { return 0.5 * (1.0 + std::erf(x / std::sqrt(2.0))); };
  const auto main_cue = [&](std::size_t a, std::size_t b) {
    std::size_t best = 0;
    for (std::size_t c = 1; c < kCueCount; ++c)
      if (dp(a, b, c) > dp(a, b, best)) best = c;
    return best;
  };
  const auto cell = [&](std::size_t r, std::size_t i, std::size_t partner, std::size_t c) {
    std::vector<std::size_t> bounders;
    for (std::size_t m = 0; m < n; ++m)
      if (m != r && dp(r, m, c) > 0.0 && (m == partner || main_cue(r, m) == c)) bounders.push_back(m);
    if (bounders.empty()) return 1.0;
    std::size_t q = bounders[0];
    for (const std::size_t m : bounders)
      if (dp(r, m, c) < dp(r, q, c)) q = m;
    const auto same_side = [&](std::size_t m) {
      return m == q || std::pow(dp(q, m, c), 2) < std::pow(dp(r, m, c), 2) + std::pow(dp(r, q, c), 2);
    };
    double up = HUGE_VAL, down = HUGE_VAL;  // the cell's half-widths toward q and away from it
    for (const std::size_t m : bounders) {
      double e2 = 0.0;
      for (std::size_t o = 0; o < kCueCount; ++o)
        if (o != c && m != partner) e2 += std::pow(dp(r, m, o), 2);
      const double half = (std::pow(dp(r, m, c), 2) + e2) / (2.0 * dp(r, m, c));
      (same_side(m) ? up : down) = std::min(same_side(m) ? up : down, half);
    }
    const double x = dp(i, r, c) > 0.0 && !same_side(i) ? -dp(i, r, c) : dp(i, r, c);
    return phi(up - x) - phi(-down - x);
  };
  std::vector<double> p(n);
  double total = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    p[j] = 1.0;
    for (std::size_t c = 0; c < kCueCount && j != presented; ++c) {
      if (dp(presented, j, c) > 0.0) p[j] *= cell(j, presented, presented, c) / cell(presented, presented, j, c);
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
