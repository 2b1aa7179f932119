// Outlines drawn at screen resolution and in bounded runs (the 250 000-point polygon crash).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "editor/core/polyline_lod.hpp"

namespace vimg::editor {
namespace {

std::vector<Point2Px> circle(std::size_t n, float radius_px) {
  std::vector<Point2Px> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    p[i] = {static_cast<float>(500 + radius_px * std::cos(t)), static_cast<float>(400 + radius_px * std::sin(t))};
  }
  return p;
}

TEST(PolylineLod, DenseOutlinesShrinkToAboutOnePointPerStep) {
  const auto in = circle(250'000, 100.0f);  // perimeter about 628 px
  std::vector<Point2Px> out;
  decimate_polyline_px(in, 1.0f, true, out);
  EXPECT_LE(out.size(), 640u);
  EXPECT_GE(out.size(), 600u);
  EXPECT_EQ(out.front().x, in.front().x);
  EXPECT_EQ(out.back().x, in.front().x);  // closed: ends where it started
  EXPECT_EQ(out[out.size() - 2].x, in.back().x);
  // Every dropped point is within one step of a kept neighbour: the shape is kept.
  for (std::size_t i = 1; i + 2 < out.size(); ++i) {  // up to the last kept interior point
    const float d = std::hypot(out[i].x - out[i - 1].x, out[i].y - out[i - 1].y);
    EXPECT_GE(d, 1.0f);
    EXPECT_LT(d, 1.1f);
  }
}

TEST(PolylineLod, SparseOutlinesAreKeptAsTheyAre) {
  const std::vector<Point2Px> square{{0, 0}, {50, 0}, {50, 50}, {0, 50}};
  std::vector<Point2Px> out;
  decimate_polyline_px(square, 1.0f, false, out);
  ASSERT_EQ(out.size(), 4u);
  decimate_polyline_px(square, 1.0f, true, out);
  ASSERT_EQ(out.size(), 5u);
}

TEST(PolylineLod, RunsAreBoundedAndChainWithoutGaps) {
  std::vector<Point2Px> points(5000);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {static_cast<float>(i), 0.0f};
  std::size_t covered = 0;
  const Point2Px* previous_end = nullptr;
  for_each_stroke_run(points, [&](const Point2Px* first, std::size_t count) {
    EXPECT_LE(count, kMaxRunPoints);
    EXPECT_GE(count, 2u);
    if (previous_end) {
      EXPECT_EQ(first, previous_end);  // each run starts where the last ended
    }
    previous_end = first + count - 1;
    covered += count - 1;
  });
  EXPECT_EQ(covered, points.size() - 1);
  EXPECT_EQ(previous_end, &points.back());
}

}  // namespace
}  // namespace vimg::editor
