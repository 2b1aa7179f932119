#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "primitives/geometry/hit_test.hpp"
#include "primitives/geometry/segment_overlap.hpp"

namespace vimg {
namespace {

constexpr int kDense = 4000;

// Compares an overlap summary with dense sampling of the segment against the point test.
template <class Shape>
void expect_matches_dense_sampling(const Shape& shape, const SegmentOverlap& o, const Vec2& p0, const Vec2& p1) {
  const double step = 1.0 / kDense;
  int inside_count = 0;
  double first = -1.0, last = -1.0;
  for (int i = 0; i <= kDense; ++i) {
    const double t = i * step;
    if (contains(shape, lerp(p0, p1, t))) {
      ++inside_count;
      if (first < 0.0) first = t;
      last = t;
    }
  }
  // Every boundary crossing can move one sample in or out.
  const double tolerance = 2.5 * step;
  if (inside_count > 1) {
    ASSERT_TRUE(o.any);
    EXPECT_NEAR(o.first_entry, first, tolerance);
    EXPECT_NEAR(o.last_exit, last, tolerance);
  }
  EXPECT_NEAR(o.inside_fraction, inside_count * step, 8 * tolerance);
  EXPECT_EQ(o.inside_at_end, contains(shape, p1));
}

struct Rng {
  std::mt19937 engine{12345};
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(engine); }
  int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(engine); }
  Vec2 point(double half) { return {uniform(-half, half), uniform(-half, half)}; }
  Vec2 grid_point(int half_mm) { return {integer(-half_mm, half_mm) * 1e-3, integer(-half_mm, half_mm) * 1e-3}; }
};

TEST(Geometry, ConvexOverlapsAgreeWithDenseSampling) {
  Rng rng;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec2 p0 = rng.point(0.02), p1 = rng.point(0.02);
    const Disc disc{rng.point(0.01), rng.uniform(0.0005, 0.012)};
    expect_matches_dense_sampling(disc, summarize(overlap(disc, p0, p1)), p0, p1);
    const Capsule capsule{rng.point(0.01), rng.point(0.01), rng.uniform(0.0002, 0.004)};
    expect_matches_dense_sampling(capsule, summarize(overlap(capsule, p0, p1)), p0, p1);
    const Vec2 a = rng.point(0.015), b = rng.point(0.015);
    const Rect rect{{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
    expect_matches_dense_sampling(rect, summarize(overlap(rect, p0, p1)), p0, p1);
    const Ellipse ellipse{rng.point(0.01), rng.uniform(0.001, 0.015), rng.uniform(0.001, 0.015)};
    expect_matches_dense_sampling(ellipse, summarize(overlap(ellipse, p0, p1)), p0, p1);
    if (testing::Test::HasFailure()) FAIL() << "trial " << trial;
  }
}

Polygon random_grid_polygon(Rng& rng) {
  // A star-shaped polygon with vertices on a 1 mm grid; rounding may make it non-simple, which
  // the even-odd rule still defines.
  const int n = rng.integer(3, 9);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(rng.uniform(0.0, 2.0 * std::numbers::pi));
  std::sort(angles.begin(), angles.end());
  Polygon polygon;
  for (const double a : angles) {
    const double r = rng.uniform(2.0, 12.0);
    polygon.vertices.push_back({std::round(r * std::cos(a)) * 1e-3, std::round(r * std::sin(a)) * 1e-3});
  }
  return polygon;
}

TEST(Geometry, PolygonOverlapsAgreeWithDenseSamplingOnGridPaths) {
  Rng rng;
  for (int trial = 0; trial < 300; ++trial) {
    const Polygon polygon = random_grid_polygon(rng);
    const auto& v = polygon.vertices;
    Vec2 p0, p1;
    switch (trial % 4) {
      case 0:  // arbitrary
        p0 = rng.point(0.015);
        p1 = rng.point(0.015);
        break;
      case 1:  // grid to grid: often through vertices and along edges
        p0 = rng.grid_point(14);
        p1 = rng.grid_point(14);
        break;
      case 2: {  // along an edge, extended both ways
        const std::size_t i = rng.integer(0, static_cast<int>(v.size()) - 1);
        const Vec2 a = v[i], b = v[(i + 1) % v.size()];
        p0 = lerp(a, b, -0.5);
        p1 = lerp(a, b, 1.5);
        break;
      }
      default: {  // through a vertex from a grid point
        const std::size_t i = rng.integer(0, static_cast<int>(v.size()) - 1);
        p0 = rng.grid_point(14);
        p1 = lerp(p0, v[i], 2.0);
        break;
      }
    }
    if (p0 == p1) continue;
    expect_matches_dense_sampling(polygon, overlap_summary(polygon, p0, p1), p0, p1);
    if (testing::Test::HasFailure()) FAIL() << "trial " << trial;
  }
}

TEST(Geometry, PolygonBoundaryCountsAsInside) {
  const Polygon square{{{0, 0}, {0.01, 0}, {0.01, 0.01}, {0, 0.01}}};
  EXPECT_TRUE(contains(square, {0.005, 0.0}));   // on an edge
  EXPECT_TRUE(contains(square, {0.01, 0.01}));   // on a vertex
  EXPECT_TRUE(contains(square, {0.0, 0.005}));
  EXPECT_FALSE(contains(square, {0.0100001, 0.005}));
  // A diamond: the +x ray from its centre passes exactly through the vertex (10, 5).
  const Polygon diamond{{{0, 0.005}, {0.005, 0}, {0.01, 0.005}, {0.005, 0.01}}};
  EXPECT_TRUE(contains(diamond, {0.005, 0.005}));
  EXPECT_FALSE(contains(diamond, {-0.001, 0.005}));  // the ray passes two vertices
  EXPECT_FALSE(contains(diamond, {0.011, 0.005}));
}

TEST(Geometry, PolygonSegmentEdgeCases) {
  const Polygon square{{{0, 0}, {0.01, 0}, {0.01, 0.01}, {0, 0.01}}};
  // Sliding along the bottom edge: on the boundary all the way.
  const auto along = overlap_summary(square, {-0.01, 0}, {0.02, 0});
  EXPECT_TRUE(along.any);
  EXPECT_NEAR(along.first_entry, 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(along.last_exit, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(along.inside_fraction, 1.0 / 3.0, 1e-12);
  // Grazing a corner only: touches, with no length inside.
  const auto corner = overlap_summary(square, {-0.005, 0.005}, {0.005, -0.005});
  EXPECT_TRUE(corner.any);
  EXPECT_NEAR(corner.inside_fraction, 0.0, 1e-12);
  EXPECT_NEAR(corner.first_entry, 0.5, 1e-12);
  // A U shape crossed through both arms: two intervals.
  const Polygon u{{{0, 0}, {0.03, 0}, {0.03, 0.03}, {0.02, 0.03}, {0.02, 0.01}, {0.01, 0.01}, {0.01, 0.03}, {0, 0.03}}};
  const auto arms = overlap_summary(u, {-0.01, 0.02}, {0.04, 0.02});
  EXPECT_NEAR(arms.first_entry, 0.2, 1e-12);
  EXPECT_NEAR(arms.last_exit, 0.8, 1e-12);
  EXPECT_NEAR(arms.inside_fraction, 0.4, 1e-12);
  EXPECT_FALSE(arms.inside_at_end);
  // Through the notch vertices exactly (y = 10 mm runs along the notch's bottom edge).
  const auto notch = overlap_summary(u, {-0.01, 0.01}, {0.04, 0.01});
  EXPECT_NEAR(notch.inside_fraction, 0.6, 1e-12);
}

TEST(Geometry, ManyCrossingsSplitTheSegmentWithoutLosingAny) {
  // A comb with 50 teeth: a segment across it meets 100 edges, more than one pass collects.
  Polygon comb;
  for (int i = 0; i < 50; ++i) {
    comb.vertices.push_back({i * 2e-3, 0.01});
    comb.vertices.push_back({i * 2e-3 + 1e-3, 0.01});
    comb.vertices.push_back({i * 2e-3 + 1e-3, 0.001});
    comb.vertices.push_back({i * 2e-3 + 2e-3, 0.001});
  }
  comb.vertices.push_back({0.1, 0.0});
  comb.vertices.push_back({0.0, 0.0});
  const auto o = overlap_summary(comb, {-0.01, 0.005}, {0.11, 0.005});
  EXPECT_NEAR(o.inside_fraction, 0.05 / 0.12, 1e-9);
  EXPECT_NEAR(o.first_entry, 0.01 / 0.12, 1e-9);
}

TEST(Geometry, DegenerateShapesAndSegments) {
  EXPECT_FALSE(overlap(Ellipse{{0, 0}, 0.0, 1.0}, {-1, 0}, {1, 0}).has_value());
  const auto still_inside = overlap(Disc{{0, 0}, 1.0}, {0.5, 0}, {0.5, 0});
  ASSERT_TRUE(still_inside.has_value());
  EXPECT_EQ(still_inside->begin, 0.0);
  EXPECT_EQ(still_inside->end, 1.0);
  EXPECT_FALSE(overlap(Disc{{0, 0}, 1.0}, {1.5, 0}, {1.5, 0}).has_value());
  const Capsule point_capsule{{0, 0}, {0, 0}, 0.001};
  const auto through = overlap(point_capsule, {-0.002, 0}, {0.002, 0});
  ASSERT_TRUE(through.has_value());
  EXPECT_NEAR(through->begin, 0.25, 1e-12);
  EXPECT_NEAR(through->end, 0.75, 1e-12);
  EXPECT_FALSE(contains(Polygon{{{0, 0}, {1, 1}}}, {0.5, 0.5}));
}

TEST(Geometry, BoundingBoxesContainTheirShapes) {
  Rng rng;
  for (int trial = 0; trial < 200; ++trial) {
    const Polygon polygon = random_grid_polygon(rng);
    const Capsule capsule{rng.point(0.01), rng.point(0.01), rng.uniform(0.0002, 0.004)};
    const Ellipse ellipse{rng.point(0.01), rng.uniform(0.001, 0.015), rng.uniform(0.001, 0.015)};
    for (int i = 0; i < 200; ++i) {
      const Vec2 p = rng.point(0.03);
      EXPECT_TRUE(!contains(polygon, p) || bounding_box(polygon).contains(p));
      EXPECT_TRUE(!contains(capsule, p) || bounding_box(capsule).contains(p));
      EXPECT_TRUE(!contains(ellipse, p) || bounding_box(ellipse).contains(p));
    }
  }
}

}  // namespace
}  // namespace vimg
