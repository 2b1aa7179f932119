#pragma once
// The 95 % intervals that `vimg study fit` states (docs/studies.md, "Fitting the model"): a
// bootstrap over participants (Efron & Tibshirani 1993, ch. 13, percentile intervals; Davison &
// Hinkley 1997, section 3.8, resampling the units that were sampled). Participants differ, and
// the trials of one participant are not independent of each other; resampling whole participants
// carries both into the interval, where a likelihood on the pooled trials carries neither.
//
//   replicate b: draw as many participants as there are, with replacement (splitmix64 seeded with
//                mix64(seed + (b + 1) G), primitives/random/splitmix64.hpp: the same intervals
//                everywhere, on any number of threads), pool their counts, fit the same free
//                constants from the full data's optimum (Nelder-Mead to kBootstrapTolerance in
//                -ln L: a percentile needs no finer)
//   interval:    the expanded percentile interval (Hesterberg 2015, The American Statistician 69,
//                "What teachers should know about the bootstrap"): plain percentiles
//                are too narrow for few units (their spread is that of a sample of n, divided by n,
//                not n - 1, and they take z where t is due), so the tails are taken at
//                  a' = Phi(-sqrt(n / (n - 1)) t_{n-1, 1 - a/2}),  a = 1 - confidence
//                (n = 10: 0.85 % and 99.15 % for a 95 % interval), n the participants; each
//                percentile by linear interpolation between order statistics (R's type 7), on the
//                search coordinate (the percentiles do not depend on it: the maps are monotone)
//   an end within 1e-3 of the search box's edge is at the edge: a lapse rate of 0 or 0.5, a weight
//                of 0 or unbounded
//
// Coverage, checked on simulated participants who differ from each other over many seeds:
// tests/study_fit/fit_coverage_test.cpp.
//
// Threads: the replicates are fitted on `threads` workers (storage/parallel_tasks.hpp); the
// caller's thread waits. Progress is reported from the caller's thread.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "study/fit_likelihood.hpp"

namespace vimg::study {

inline constexpr std::uint64_t kBootstrapSeed = 20261129;
inline constexpr std::size_t kBootstrapReplicates = 1000;
inline constexpr double kBootstrapTolerance = 1e-5;
inline constexpr std::size_t kBootstrapChunk = 100;  // replicates per line of progress
// The fewest participants the coverage test checks; with fewer, `vimg study fit` warns.
inline constexpr std::size_t kBootstrapCheckedParticipants = 10;

struct BootstrapOptions {
  std::size_t replicates = kBootstrapReplicates;
  std::uint64_t seed = kBootstrapSeed;
  double confidence = 0.95;
  int threads = 0;  // <= 0: one per core
  void (*progress)(const std::string& line) = nullptr;  // a line per kBootstrapChunk replicates; null: silent
};

struct BootstrapEnd {
  double theta = 0.0;    // the percentile, on the search coordinate
  bool at_edge = false;  // within 1e-3 of the box's edge
};

struct BootstrapIntervals {
  std::vector<BootstrapEnd> lower, upper;  // per free constant, in `free`'s order
};

// Needs at least one participant. `start`: the optimum of `free` on all of `data`.
BootstrapIntervals bootstrap_over_participants(const FitData& data, const std::vector<std::size_t>& free,
                                               const std::vector<double>& start, const DiscriminationConstants& defaults,
                                               const BootstrapOptions& options = {});

// a' above: the share of the resamples below the interval's lower end (and above its upper end).
double expanded_tail(double confidence, std::size_t participants);

// The q-quantile of `values` (sorted in place), R's type 7: linear between order statistics.
double quantile_type7(std::vector<double>& values, double q);

}  // namespace vimg::study
