// The seeded trial order (study/trial_plan.hpp): reproducible from study seed and participant,
// different per participant, every image `repetitions` times per set, blocked and interleaved
// location plans, distinct data seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

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

TEST(TrialPlan, FixedValuesOnEveryPlatform) {
  // Pinned: a change of generator or mixing would change every participant's order.
  EXPECT_EQ(participant_seed(2024, "P01"), participant_seed(2024, "P01"));
  EXPECT_EQ(shuffled_indices(8, 42), (std::vector<std::size_t>{3, 1, 6, 2, 4, 0, 7, 5}));
  EXPECT_EQ(participant_seed(7, "P01"), 15220198599442192890u);
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

TEST(TrialPlan, MatchingPlanIsReproducibleAndPerParticipant) {
  const MatchingStudy s = matching_study();
  EXPECT_TRUE(same(plan_matching_trials(s, "P01"), plan_matching_trials(s, "P01")));
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

LocationStudy location_study(TrialOrder order) {
  LocationStudy s;
  s.seed = 7;
  s.trials_per_metaphor = 7;
  s.order = order;
  return s;
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

TEST(TrialPlan, LocationDataSeedsAreDistinctAndReproducible) {
  for (const TrialOrder order : {TrialOrder::blocked, TrialOrder::interleaved}) {
    LocationStudy s = location_study(order);
    s.trials_per_metaphor = 500;
    const auto plan = plan_location_trials(s, "P01");
    std::set<std::uint64_t> seeds;
    for (const auto& t : plan) seeds.insert(t.data_seed);
    EXPECT_EQ(seeds.size(), plan.size());
    const auto again = plan_location_trials(s, "P01");
    const auto other = plan_location_trials(s, "P02");
    for (std::size_t k = 0; k < plan.size(); ++k) {
      EXPECT_EQ(again[k].data_seed, plan[k].data_seed);
      EXPECT_EQ(again[k].metaphor, plan[k].metaphor);
      EXPECT_NE(other[k].data_seed, plan[k].data_seed);
    }
  }
}

}  // namespace
}  // namespace vimg::study
