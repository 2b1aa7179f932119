#include "editor/core/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vimg::editor {
namespace {

constexpr double kPpm = 4.0;  // px per mm: a click is a drag under 0.75 mm

TEST(Placement, ADragPlacesTheShapeSpannedByItsEnds) {
  const Point2Mm a{10, 20}, b{40, 60};
  const auto dot = place_element(Tool::dot, a, b, kPpm);
  ASSERT_TRUE(dot && std::holds_alternative<Dot>(dot->body));
  EXPECT_DOUBLE_EQ(std::get<Dot>(dot->body).radius_mm, std::hypot(30.0, 40.0));
  const auto line = place_element(Tool::line, a, b, kPpm);
  ASSERT_TRUE(line);
  const Line& l = std::get<Line>(line->body);
  EXPECT_EQ((std::array{l.x1_mm, l.y1_mm, l.x2_mm, l.y2_mm}), (std::array{10.0, 20.0, 40.0, 60.0}));
  // Corners in any order give the same box.
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, a}}) {
    const auto rect = place_element(Tool::rect, p, q, kPpm);
    ASSERT_TRUE(rect);
    EXPECT_EQ(*element_bounds(*rect), (RectMm{10, 20, 40, 60}));
    const auto ellipse = place_element(Tool::ellipse, p, q, kPpm);
    ASSERT_TRUE(ellipse);
    const Surface& s = std::get<Surface>(ellipse->body);
    EXPECT_EQ((std::array{s.cx_mm, s.cy_mm, s.rx_mm, s.ry_mm}), (std::array{25.0, 40.0, 15.0, 20.0}));
  }
}

TEST(Placement, AClickPlacesTheDefaultSize) {
  const Point2Mm a{10, 20}, b{10.5, 20};  // 2 px on screen
  EXPECT_DOUBLE_EQ(std::get<Dot>(place_element(Tool::dot, a, b, kPpm)->body).radius_mm, 2.0);
  EXPECT_DOUBLE_EQ(std::get<Line>(place_element(Tool::line, a, b, kPpm)->body).x2_mm, 30.0);
  EXPECT_EQ(*element_bounds(*place_element(Tool::rect, a, b, kPpm)), (RectMm{10, 20, 30, 40}));
  EXPECT_EQ(*element_bounds(*place_element(Tool::ellipse, a, b, kPpm)), (RectMm{0, 10, 20, 30}));
  EXPECT_FALSE(place_element(Tool::select, a, b, kPpm));
  EXPECT_FALSE(place_element(Tool::polygon, a, b, kPpm));
}

TEST(Placement, APolygonNeedsThreePoints) {
  EXPECT_FALSE(polygon_element({{0, 0}, {1, 0}}));
  const auto p = polygon_element({{0, 0}, {10, 0}, {5, 8}});
  ASSERT_TRUE(p);
  EXPECT_EQ(std::get<Surface>(p->body).points.size(), 3u);
}

TEST(Placement, HandlesSitOnTheBoxClockwiseFromTopLeft) {
  const RectMm box{0, 0, 20, 10};
  const Point2Mm want[8] = {{0, 0}, {10, 0}, {20, 0}, {20, 5}, {20, 10}, {10, 10}, {0, 10}, {0, 5}};
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(handle_position(box, i).x_mm, want[i].x_mm) << i;
    EXPECT_EQ(handle_position(box, i).y_mm, want[i].y_mm) << i;
  }
}

// Property: a handle moves exactly the edges it sits on, by the drag; the other edges stay.
TEST(Placement, AHandleMovesOnlyItsEdgesByTheDrag) {
  const RectMm from{10, 10, 30, 20};
  for (int h = 0; h < 8; ++h) {
    const RectMm r = resized_box(from, h, 3.0, -2.0, 0.0);
    const int col = kHandleColumn[static_cast<std::size_t>(h)];
    const int row = kHandleRow[static_cast<std::size_t>(h)];
    EXPECT_DOUBLE_EQ(r.x0_mm, from.x0_mm + (col == 0 ? 3.0 : 0.0)) << h;
    EXPECT_DOUBLE_EQ(r.x1_mm, from.x1_mm + (col == 2 ? 3.0 : 0.0)) << h;
    EXPECT_DOUBLE_EQ(r.y0_mm, from.y0_mm + (row == 0 ? -2.0 : 0.0)) << h;
    EXPECT_DOUBLE_EQ(r.y1_mm, from.y1_mm + (row == 2 ? -2.0 : 0.0)) << h;
  }
}

// Snapping a resize rounds the drag to whole steps, as a move does: the moved edge stays a whole
// number of steps from where it was, and within half a step of the mouse.
TEST(Placement, ASnappedResizeMovesTheEdgeByWholeSteps) {
  const RectMm from{10.3, 10.3, 30.3, 20.3};
  const double step = 2.0;
  for (double dx = -7.0; dx <= 7.0; dx += 0.37) {
    const RectMm r = resized_box(from, 3, dx, 0.0, step);  // the right edge
    const double moved = r.x1_mm - from.x1_mm;
    EXPECT_NEAR(std::remainder(moved, step), 0.0, 1e-9) << dx;
    EXPECT_LE(std::abs(moved - dx), step / 2 + 1e-9) << dx;
    EXPECT_DOUBLE_EQ(r.x0_mm, from.x0_mm);
  }
}

TEST(Placement, ABoxIsNeverFlippedNorEmptiedByAHandle) {
  const RectMm from{10, 10, 30, 20};
  const RectMm r = resized_box(from, 0, 100.0, 100.0, 0.0);  // top-left dragged past bottom-right
  EXPECT_DOUBLE_EQ(r.x0_mm, 30 - kMinResizedSideMm);
  EXPECT_DOUBLE_EQ(r.y0_mm, 20 - kMinResizedSideMm);
  EXPECT_DOUBLE_EQ(r.x1_mm, 30);
  EXPECT_DOUBLE_EQ(r.y1_mm, 20);
}

}  // namespace
}  // namespace vimg::editor
