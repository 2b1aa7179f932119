#pragma once
// Simulated studies for the fit's unit tests: sets of images as points in the level-pitch-envelope
// space (JND units), and participants who choose by a known model (tests/study_fit/fit_simulation.hpp),
// all alike or each with constants of their own.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "study/fit_model.hpp"
#include "tests/study_fit/fit_simulation.hpp"

namespace vimg::fit_test {

using study::ChoiceCounts;
using study::FitData;

// |x_i - x_j| per cue of points in cue space (JND units).
inline CueMatrix cues_of(const std::vector<CueDistances>& points) {
  CueMatrix m(points.size(), std::vector<CueDistances>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < points.size(); ++j) {
      for (std::size_t c = 0; c < kCueCount; ++c) m[i][j][c] = std::abs(points[i][c] - points[j][c]);
    }
  }
  return m;
}

// Two sets of four images in the level-pitch-envelope space (identified 60-90 % of the time by the
// known truth: confused enough to inform the weights, distinct enough to inform the lapse rate).
inline FitData two_sets() {
  FitData d;
  d.set_names = {"near", "far"};
  d.set_cues = {cues_of({{0, 0, 0}, {1.5, 0, 0}, {0, 1.8, 0}, {0.75, 0.75, 1.5}}),
                cues_of({{0, 0, 0}, {3, 0.75, 0}, {0.45, 3, 0.75}, {1.5, 1.5, 3}})};
  return d;
}

inline DiscriminationConstants known_truth() {
  DiscriminationConstants t;
  t.lapse_rate = 0.08;
  t.cue_weight = {2.0, 0.5, 1.4};
  return t;
}

// One participant's counts: every image of every set presented `repetitions` times, chosen by `k`.
inline std::vector<ChoiceCounts> participant_counts(const FitData& d, const DiscriminationConstants& k, int repetitions,
                                                    SplitMix& random) {
  std::vector<ChoiceCounts> sets;
  for (const CueMatrix& cues : d.set_cues) {
    ChoiceCounts counts(cues.size(), std::vector<double>(cues.size(), 0.0));
    for (std::size_t i = 0; i < cues.size(); ++i) {
      const std::vector<double> row = choice_row(cues, i, k);
      for (int r = 0; r < repetitions; ++r) counts[i][draw(row, random)] += 1.0;
    }
    sets.push_back(counts);
  }
  return sets;
}

// `participants` participants P1, P2, ..., all choosing by `truth`.
inline void simulate(FitData& d, const DiscriminationConstants& truth, std::size_t participants, int repetitions,
                     std::uint64_t seed) {
  SplitMix random(seed);
  for (std::size_t p = 0; p < participants; ++p) {
    d.participants.push_back("P" + std::to_string(p + 1));
    d.counts.push_back(participant_counts(d, truth, repetitions, random));
  }
}

// A standard normal draw (Box-Muller on two uniforms of `random`).
inline double normal(SplitMix& random) {
  const double u = 1.0 - random.unit();  // (0, 1]
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * 3.141592653589793 * random.unit());
}

// How participants differ: each one's weights are the population's times exp(spread_ln z_c), and
// their lapse rate the population's times exp(spread_ln z_0), z standard normal.
inline DiscriminationConstants participant_constants(const DiscriminationConstants& population, double spread_ln,
                                                     SplitMix& random) {
  DiscriminationConstants k = population;
  k.lapse_rate = std::min(0.5, population.lapse_rate * std::exp(spread_ln * normal(random)));
  for (double& w : k.cue_weight) w *= std::exp(spread_ln * normal(random));
  return k;
}

inline const study::ConstantFit& constant(const study::ModelFit& fit, const std::string& name) {
  for (const study::ConstantFit& c : fit.report) {
    if (c.name == name) return c;
  }
  ADD_FAILURE() << "no constant " << name;
  return fit.report.front();
}

}  // namespace vimg::fit_test
