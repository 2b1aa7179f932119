// The seeded trial order (study/trial_plan.hpp): whole plans pinned for fixed seeds (computed
// outside this code from the documented definition), different per participant, every image
// `repetitions` times per set, blocked and interleaved location plans, distinct data seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "study/trial_plan.hpp"

namespace vimg::study {
namespace {

MatchingStudy matching_study(int repetitions = 5) {
  MatchingStudy s;
  s.seed = 2024;
  s.repetitions = repetitions;
  s.sets = {{"complexity", {"dot.vimg", "line.vimg", "surface.vimg", "group.vimg"}},
            {"same", {"a.vimg", "b.vimg", "c.vimg"}}};
  return s;
}

bool same(const std::vector<MatchingTrialPlan>& a, const std::vector<MatchingTrialPlan>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const auto& x, const auto& y) { return x.set == y.set && x.image == y.image; });
}

LocationStudy location_study(TrialOrder order) {
  LocationStudy s;
  s.seed = 7;
  s.trials_per_metaphor = 7;
  s.order = order;
  return s;
}

// Images of a matching plan, one digit per trial.
std::string images_of(const std::vector<MatchingTrialPlan>& plan) {
  std::string digits;
  for (const auto& t : plan) digits += static_cast<char>('0' + t.image);
  return digits;
}

// Metaphors of a location plan, R (roughness) or T (transition cue) per trial.
std::string metaphors_of(const std::vector<LocationTrialPlan>& plan) {
  std::string letters;
  for (const auto& t : plan) letters += t.metaphor == LocationMetaphor::roughness ? 'R' : 'T';
  return letters;
}

// Pinned: a participant resuming on another build (another compiler, standard library or machine)
// must get the same order, so every value below was computed outside this code, by an independent
// implementation of the definition in study/trial_plan.hpp (splitmix64, FNV-1a-64, the rejection
// draw, Fisher-Yates from the top, derive) in Python integers: trial_plan_reference.py beside this
// file, which checks these pins and ~120 more cases against this code (trial_plan_reference_test.cpp). The generator is Vigna's splitmix64
// (prng.di.unimi.it/splitmix64.c), whose outputs are standardised: from state 0 its first is
// 0xE220A8397B1DCDAF, which alone fixes the first swap of shuffled_indices(10, 0) (5 at the end:
// 2^64 mod 10 = 6 rejects nothing, and 0xE220A8397B1DCDAF mod 10 = 5).
TEST(TrialPlan, FixedValuesOnEveryPlatform) {
  EXPECT_EQ(shuffled_indices(10, 0), (std::vector<std::size_t>{6, 3, 2, 9, 8, 1, 4, 7, 0, 5}));
  EXPECT_EQ(shuffled_indices(8, 42), (std::vector<std::size_t>{3, 1, 6, 2, 4, 0, 7, 5}));
  EXPECT_EQ(participant_seed(7, "P01"), 15220198599442192890u);
  EXPECT_EQ(participant_seed(2024, "P01"), 0x3D0CCE5EC8E439B1u);
}

TEST(TrialPlan, WholeMatchingPlansAreFixed) {
  // Seed 2024, a set of 4 images then one of 3, 5 repetitions: 20 then 15 trials.
  const MatchingStudy s = matching_study();
  const auto p01 = plan_matching_trials(s, "P01"), p02 = plan_matching_trials(s, "P02");
  EXPECT_EQ(images_of(p01), "23101220313302102130" "022120200112110");
  EXPECT_EQ(images_of(p02), "01021203330122133012" "011101010222202");
  for (std::size_t k = 0; k < p01.size(); ++k) EXPECT_EQ(p01[k].set, k < 20 ? 0u : 1u) << k;
}

TEST(TrialPlan, WholeLocationPlansAreFixed) {
  // Seed 7, 7 trials per metaphor.
  LocationStudy blocked = location_study(TrialOrder::blocked), interleaved = location_study(TrialOrder::interleaved);
  EXPECT_EQ(metaphors_of(plan_location_trials(blocked, "P01")), "RRRRRRRTTTTTTT");
  EXPECT_EQ(metaphors_of(plan_location_trials(blocked, "P02")), "TTTTTTTRRRRRRR");
  EXPECT_EQ(metaphors_of(plan_location_trials(blocked, "P03")), "RRRRRRRTTTTTTT");
  const auto plan = plan_location_trials(interleaved, "P01");
  EXPECT_EQ(metaphors_of(plan), "RRTTRTRRRTTTRT");
  // Trial k's data seed is derive(participant seed, 4, k), whatever the order.
  const std::vector<std::uint64_t> seeds{
      0x711D6FFDDF81414CULL, 0x342DBCA20CCA49FEULL, 0xB56FC2A90E46560EULL, 0xA9B4D4B71038012EULL, 0xECBF0A4A65EFB320ULL,
      0xCEAF31B205A48DFEULL, 0xD01082548A1436AAULL, 0xA29D8C2D92DC91D3ULL, 0xE5920097BD2C0ED8ULL, 0xD6C5068E939051B3ULL,
      0xF19604B695CC4641ULL, 0xC8641F8CF01F4070ULL, 0x81BF85C52D913D71ULL, 0xBDEA090F15188940ULL};
  const auto blocked_plan = plan_location_trials(blocked, "P01");
  ASSERT_EQ(plan.size(), seeds.size());
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    EXPECT_EQ(plan[k].data_seed, seeds[k]) << "trial " << k + 1;
    EXPECT_EQ(blocked_plan[k].data_seed, seeds[k]) << "trial " << k + 1;
  }
}

TEST(TrialPlan, ShuffleIsAPermutation) {
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    for (const std::size_t n : {0u, 1u, 2u, 7u, 100u}) {
      auto order = shuffled_indices(n, seed);
      std::sort(order.begin(), order.end());
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(order[i], i);
      ASSERT_EQ(order.size(), n);
    }
  }
}

TEST(TrialPlan, ShuffleIsUniformEnough) {
  // Each of the 6 orders of 3 items, over 60 000 seeds: within 5 % of 10 000 each.
  std::map<std::vector<std::size_t>, int> counts;
  for (std::uint64_t seed = 0; seed < 60000; ++seed) ++counts[shuffled_indices(3, seed)];
  ASSERT_EQ(counts.size(), 6u);
  for (const auto& [order, n] : counts) EXPECT_NEAR(n, 10000, 500);
}

TEST(TrialPlan, MatchingPlanIsPerParticipantAndPerStudy) {
  const MatchingStudy s = matching_study();
  EXPECT_FALSE(same(plan_matching_trials(s, "P01"), plan_matching_trials(s, "P02")));
  EXPECT_NE(participant_seed(2024, "P01"), participant_seed(2024, "P02"));
  EXPECT_NE(participant_seed(2024, "P01"), participant_seed(2025, "P01"));
  MatchingStudy other = s;
  other.seed = 2025;
  EXPECT_FALSE(same(plan_matching_trials(s, "P01"), plan_matching_trials(other, "P01")));
}

TEST(TrialPlan, MatchingPlanShowsEveryImageRepetitionsTimesPerSetInFileOrder) {
  for (const int repetitions : {1, 5}) {
    const MatchingStudy s = matching_study(repetitions);
    for (const char* participant : {"P01", "P02", "x"}) {
      const auto plan = plan_matching_trials(s, participant);
      ASSERT_EQ(plan.size(), static_cast<std::size_t>(7 * repetitions));
      std::map<std::pair<std::size_t, std::size_t>, int> shown;
      for (std::size_t k = 0; k < plan.size(); ++k) {
        ++shown[{plan[k].set, plan[k].image}];
        if (k > 0) {
          EXPECT_LE(plan[k - 1].set, plan[k].set) << "sets in file order, one after the other";
        }
      }
      ASSERT_EQ(shown.size(), 7u);
      for (const auto& [item, n] : shown) EXPECT_EQ(n, repetitions);
    }
  }
  // Shuffled within a set: not the file order.
  const auto plan = plan_matching_trials(matching_study(), "P01");
  bool in_file_order = true;
  for (std::size_t k = 0; k < 20; ++k) in_file_order = in_file_order && plan[k].image == k % 4;
  EXPECT_FALSE(in_file_order);
}

TEST(TrialPlan, BlockedLocationPlanRunsEachMetaphorInOneBlockCounterbalanced) {
  const LocationStudy s = location_study(TrialOrder::blocked);
  std::set<LocationMetaphor> first_metaphors;
  for (int p = 1; p <= 20; ++p) {
    const auto plan = plan_location_trials(s, "P" + std::to_string(p));
    ASSERT_EQ(plan.size(), 14u);
    for (std::size_t k = 1; k < 7; ++k) EXPECT_EQ(plan[k].metaphor, plan[0].metaphor);
    for (std::size_t k = 8; k < 14; ++k) EXPECT_EQ(plan[k].metaphor, plan[7].metaphor);
    EXPECT_NE(plan[0].metaphor, plan[7].metaphor);
    first_metaphors.insert(plan[0].metaphor);
  }
  EXPECT_EQ(first_metaphors.size(), 2u) << "some participants begin with each metaphor";
}

TEST(TrialPlan, InterleavedLocationPlanMixesTheMetaphors) {
  const LocationStudy s = location_study(TrialOrder::interleaved);
  bool some_mixed = false;
  for (int p = 1; p <= 10; ++p) {
    const auto plan = plan_location_trials(s, "P" + std::to_string(p));
    ASSERT_EQ(plan.size(), 14u);
    EXPECT_EQ(std::count_if(plan.begin(), plan.end(), [](const auto& t) { return t.metaphor == LocationMetaphor::roughness; }), 7);
    int switches = 0;
    for (std::size_t k = 1; k < plan.size(); ++k) switches += plan[k].metaphor != plan[k - 1].metaphor;
    some_mixed = some_mixed || switches > 1;
  }
  EXPECT_TRUE(some_mixed);
}

TEST(TrialPlan, LocationDataSeedsAreDistinctPerTrialAndParticipant) {
  for (const TrialOrder order : {TrialOrder::blocked, TrialOrder::interleaved}) {
    LocationStudy s = location_study(order);
    s.trials_per_metaphor = 500;
    const auto plan = plan_location_trials(s, "P01");
    std::set<std::uint64_t> seeds;
    for (const auto& t : plan) seeds.insert(t.data_seed);
    EXPECT_EQ(seeds.size(), plan.size());
    const auto other = plan_location_trials(s, "P02");
    for (std::size_t k = 0; k < plan.size(); ++k) {
      EXPECT_NE(other[k].data_seed, plan[k].data_seed);
    }
  }
}

}  // namespace
}  // namespace vimg::study
