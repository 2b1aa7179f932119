// bridge_rings (storage/import/rings.hpp), used by the SVG and the picture import: each further ring
// is bridged from the first ring's vertex nearest to its first point (the lowest index among equally
// near ones), as a search of every vertex finds it; the search is bounded by a work budget.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "storage/import/rings.hpp"

namespace vimg::import {
namespace {

// The nearest vertex by looking at every one: the definition.
std::size_t nearest_by_definition(const Ring& outer, Vec2 p) {
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < outer.size(); ++i) {
    const Vec2 d = outer[i] - p;
    if (dot(d, d) < best_distance) {
      best_distance = dot(d, d);
      best = i;
    }
  }
  return best;
}

// The first ring's vertex each further ring is bridged from, read off the joined point list: the
// vertex just before the ring's first point.
Ring expected_join(const std::vector<Ring>& rings) {
  const Ring& outer = rings.front();
  std::vector<std::vector<std::size_t>> attached(outer.size());
  for (std::size_t r = 1; r < rings.size(); ++r) attached[nearest_by_definition(outer, rings[r].front())].push_back(r);
  Ring out;
  for (std::size_t i = 0; i < outer.size(); ++i) {
    out.push_back(outer[i]);
    for (const std::size_t r : attached[i]) {
      out.insert(out.end(), rings[r].begin(), rings[r].end());
      out.push_back(rings[r].front());
      out.push_back(outer[i]);
    }
  }
  return out;
}

TEST(SvgRings, EachRingIsBridgedFromTheNearestVertexAsASearchOfAllFindsIt) {
  std::mt19937 random(23);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  std::uniform_int_distribution<int> grid(0, 6);  // few distinct values: many ties in x and in distance
  for (int trial = 0; trial < 200; ++trial) {
    const bool on_grid = trial % 2 == 0;
    const auto point = [&] {
      return on_grid ? Vec2{static_cast<double>(grid(random)), static_cast<double>(grid(random))}
                     : Vec2{coordinate(random), coordinate(random)};
    };
    std::vector<Ring> rings(1 + trial % 9);
    for (Ring& ring : rings) {
      for (int k = 0; k < 3 + trial % 40; ++k) ring.push_back(point());
    }
    EXPECT_EQ(bridge_rings(rings), expected_join(rings)) << "trial " << trial;
  }
  // A regular polygon around holes at its centre: every vertex about equally near.
  Ring circle;
  for (int k = 0; k < 360; ++k) circle.push_back({std::cos(k * 0.0174532925199), std::sin(k * 0.0174532925199)});
  const std::vector<Ring> centred = {circle, {{0, 0}, {0.1, 0}, {0, 0.1}}, {{0.01, 0}, {0.1, 0.1}, {0, 0.1}}};
  EXPECT_EQ(bridge_rings(centred), expected_join(centred));
}

TEST(SvgRings, TheSearchStopsPastItsWorkBudget) {
  Ring circle;
  for (int k = 0; k < 1000; ++k) circle.push_back({std::cos(k * 0.00628318530718), std::sin(k * 0.00628318530718)});
  std::vector<Ring> rings = {circle};
  for (int k = 0; k < 100; ++k) rings.push_back({{0, 0}, {0.01, 0}, {0, 0.01}});  // each looks at most vertices
  std::size_t work = 0;
  EXPECT_FALSE(bridge_rings(rings, 10'000, work).has_value());
  EXPECT_GT(work, 10'000u);
  EXPECT_LT(work, 10'000u + circle.size() + 1);  // it stops within one search of the budget
  work = 0;
  EXPECT_TRUE(bridge_rings(rings, std::numeric_limits<std::size_t>::max(), work).has_value());
}

}  // namespace
}  // namespace vimg::import
