#pragma once
// Simulated participants for the fit's tests: choices drawn from a known discrimination model
// (p(j | i) of discrimination_confusion, written out again here from its equation) with a seeded
// generator that gives the same draws on every platform (splitmix64, 53-bit uniforms; never
// std::*_distribution, whose output differs between standard libraries).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "primitives/perception/discrimination_choice.hpp"

namespace vimg::fit_test {

class SplitMix {
 public:
  explicit SplitMix(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  std::uint64_t state_;
};

// The model's choice probabilities of one presented image, from the equation of
// primitives/perception/discrimination_choice.hpp:
//   D_ij = sqrt(sum_c (w_c d_ij,c)^2),  p(j|i) = (1 - lapse) exp(-D_ij/T) / sum_k exp(-D_ik/T) + lapse / n.
inline std::vector<double> choice_row(const CueMatrix& cues, std::size_t presented, const DiscriminationConstants& k) {
  const std::size_t n = cues.size();
  std::vector<double> p(n);
  double total = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    double sum = 0.0;
    for (std::size_t c = 0; c < kCueCount; ++c) sum += std::pow(k.cue_weight[c] * cues[presented][j][c], 2);
    p[j] = std::exp(-std::sqrt(sum) / k.temperature_jnd);
    total += p[j];
  }
  for (double& x : p) x = (1.0 - k.lapse_rate) * x / total + k.lapse_rate / static_cast<double>(n);
  return p;
}

// An image drawn from `row` (probabilities summing to 1).
inline std::size_t draw(const std::vector<double>& row, SplitMix& random) {
  const double u = random.uniform();
  double cumulative = 0.0;
  for (std::size_t j = 0; j < row.size(); ++j) {
    cumulative += row[j];
    if (u < cumulative) return j;
  }
  return row.size() - 1;
}

}  // namespace vimg::fit_test
