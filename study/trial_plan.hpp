#pragma once
// One seeded trial order for both studies (pure functions). The order is reproducible from the
// study's seed and the participant's ID on every platform: the participant seed is FNV-1a (64-bit)
// of the ID mixed into the study seed with splitmix64, and shuffles are Fisher-Yates driven by the
// project's own generator (splitmix64, with an unbiased bounded draw), never std::*_distribution,
// whose output differs between standard libraries.
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

struct LocationTrialPlan {
  LocationMetaphor metaphor = LocationMetaphor::roughness;
  std::uint64_t data_seed = 0;  // make_study_set(data_seed): a new bend and plane per trial
};
// Blocked: the metaphors' order shuffled by the participant seed (counterbalanced across
// participants), trials_per_metaphor each in a row; interleaved: all trials shuffled. The data seed
// of trial k follows from the participant seed and k, and differs between the trials of one plan.
std::vector<LocationTrialPlan> plan_location_trials(const LocationStudy& study, std::string_view participant);

}  // namespace vimg::study
