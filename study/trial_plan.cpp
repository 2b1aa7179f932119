#include "study/trial_plan.hpp"

#include <numeric>
#include <utility>

#include "primitives/random/splitmix64.hpp"

namespace vimg::study {
namespace {

constexpr std::uint64_t kGolden = kSplitMixGolden;

// FNV-1a, 64 bits, of the ID's bytes.
std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t h = 0xCBF29CE484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001B3ULL;
  }
  return h;
}

// Seeds for the parts of one participant's plan, distinct for distinct (seed, purpose, index).
std::uint64_t derive(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index) {
  return mix64(mix64(seed ^ mix64(purpose * kGolden)) + index * kGolden);
}

constexpr std::uint64_t kSetShuffle = 1, kMetaphorOrder = 2, kLocationShuffle = 3, kDataSeed = 4;

}  // namespace

std::uint64_t participant_seed(std::uint64_t study_seed, std::string_view participant) {
  return mix64(mix64(study_seed + kGolden) ^ fnv1a64(participant));
}

std::vector<std::size_t> shuffled_indices(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  SplitMix64 rng(seed);
  for (std::size_t i = n; i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.below(i));
    std::swap(order[i - 1], order[j]);
  }
  return order;
}

std::vector<MatchingTrialPlan> plan_matching_trials(const MatchingStudy& study, std::string_view participant) {
  const std::uint64_t seed = participant_seed(study.seed, participant);
  std::vector<MatchingTrialPlan> plan;
  for (std::size_t s = 0; s < study.sets.size(); ++s) {
    std::vector<MatchingTrialPlan> block;
    for (int r = 0; r < study.repetitions; ++r) {
      for (std::size_t i = 0; i < study.sets[s].images.size(); ++i) block.push_back({s, i});
    }
    for (const std::size_t k : shuffled_indices(block.size(), derive(seed, kSetShuffle, s))) plan.push_back(block[k]);
  }
  return plan;
}

std::vector<std::size_t> trial_sets(const std::vector<MatchingTrialPlan>& plan) {
  std::vector<std::size_t> sets;
  sets.reserve(plan.size());
  for (const MatchingTrialPlan& trial : plan) sets.push_back(trial.set);
  return sets;
}

std::vector<LocationTrialPlan> plan_location_trials(const LocationStudy& study, std::string_view participant) {
  const std::uint64_t seed = participant_seed(study.seed, participant);
  std::vector<LocationMetaphor> metaphors;
  if (study.order == TrialOrder::blocked) {
    for (const std::size_t m : shuffled_indices(study.metaphors.size(), derive(seed, kMetaphorOrder, 0))) {
      for (int t = 0; t < study.trials_per_metaphor; ++t) metaphors.push_back(study.metaphors[m]);
    }
  } else {
    std::vector<LocationMetaphor> all;
    for (const LocationMetaphor m : study.metaphors) {
      for (int t = 0; t < study.trials_per_metaphor; ++t) all.push_back(m);
    }
    for (const std::size_t k : shuffled_indices(all.size(), derive(seed, kLocationShuffle, 0))) metaphors.push_back(all[k]);
  }
  std::vector<LocationTrialPlan> plan;
  plan.reserve(metaphors.size());
  for (std::size_t k = 0; k < metaphors.size(); ++k) {
    // Trial k + 1's data set: distinct seeds for distinct trials (derive is injective in its index).
    plan.push_back({metaphors[k], derive(seed, kDataSeed, k + 1)});
  }
  return plan;
}

}  // namespace vimg::study
