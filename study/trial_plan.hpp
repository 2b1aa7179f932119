#pragma once
// One seeded trial order for both studies (pure functions). The order is reproducible from the
// study's seed and the participant's ID on every platform, never from std::*_distribution (whose
// output differs between standard libraries):
//   mix64(z)            splitmix64's output function (a bijection of 64-bit words)
//   participant_seed    mix64(mix64(study_seed + G) ^ FNV-1a-64(ID bytes)), G = 0x9E3779B97F4A7C15
//   generator           splitmix64: state += G, output mix64(state); a draw below n rejects outputs
//                       under 2^64 mod n (no modulo bias)
//   shuffled_indices    Fisher-Yates from the top: for i = n..2, swap [i-1] with [draw below i]
//   part seeds          derive(seed, purpose, index) = mix64(mix64(seed ^ mix64(purpose * G)) + index * G):
//                       purpose 1 a set's shuffle (index: the set), 2 the metaphors' order, 3 the
//                       interleaved shuffle, 4 a trial's data seed (index: the trial number, from 1)
//   matching plan       per set s in file order: the list of images 0..m-1 repeated `repetitions`
//                       times (the image index runs fastest), trial k of the set is list[order[k]]
//                       with order = shuffled_indices(list size, derive(participant seed, 1, s))
//   location plan       blocked: the metaphors (file order) taken in shuffled_indices(count,
//                       derive(participant seed, 2, 0)), each trials_per_metaphor times in a row;
//                       interleaved: [metaphor 0 x t, metaphor 1 x t, ...] taken in shuffled_indices(
//                       size, derive(participant seed, 3, 0)); trial k's data seed derive(.., 4, k)
// tests/study_core/trial_plan_reference.py is an independent implementation of this definition.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "storage/study/study_file.hpp"

namespace vimg::study {

std::uint64_t participant_seed(std::uint64_t study_seed, std::string_view participant);

// A permutation of 0..n-1, the same for the same seed everywhere.
std::vector<std::size_t> shuffled_indices(std::size_t n, std::uint64_t seed);

// Trial k (1-based) is plan[k - 1]: the set (index into MatchingStudy::sets) and the image presented
// (index into that set's images).
struct MatchingTrialPlan {
  std::size_t set = 0;
  std::size_t image = 0;
};
// Sets in file order (a pause between sets); within a set every image `repetitions` times, shuffled.
std::vector<MatchingTrialPlan> plan_matching_trials(const MatchingStudy& study, std::string_view participant);
// The set of each trial of a plan: what the readers of per-trial files (storage) need of it.
std::vector<std::size_t> trial_sets(const std::vector<MatchingTrialPlan>& plan);

struct LocationTrialPlan {
  LocationMetaphor metaphor = LocationMetaphor::roughness;
  std::uint64_t data_seed = 0;  // make_study_set(data_seed): a new bend and plane per trial
};
// Blocked: the metaphors' order shuffled by the participant seed (counterbalanced across
// participants), trials_per_metaphor each in a row; interleaved: all trials shuffled. The data seed
// of trial k follows from the participant seed and k, and differs between the trials of one plan.
std::vector<LocationTrialPlan> plan_location_trials(const LocationStudy& study, std::string_view participant);

}  // namespace vimg::study
