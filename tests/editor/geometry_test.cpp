#include "editor/core/geometry.hpp"

#include <gtest/gtest.h>

#include "editor/core/viewport.hpp"

namespace vimg::editor {
namespace {

Element element(auto body) {
  Element e;
  e.body = body;
  return e;
}

TEST(Geometry, LineBoundsIncludeTheBand) {
  Line l;
  l.x1_mm = 10;
  l.y1_mm = 20;
  l.x2_mm = 30;
  l.y2_mm = 20;
  l.width_mm = 2;
  EXPECT_EQ(*element_bounds(element(l)), (RectMm{9, 19, 31, 21}));
  EXPECT_TRUE(element_contains(element(l), {20, 20.9}, 0));
  EXPECT_FALSE(element_contains(element(l), {20, 21.1}, 0));
}

TEST(Geometry, EllipseAndPolygonContainment) {
  Surface e;
  e.shape = SurfaceShape::ellipse;
  e.cx_mm = 50;
  e.cy_mm = 50;
  e.rx_mm = 20;
  e.ry_mm = 10;
  EXPECT_TRUE(element_contains(element(e), {69, 50}, 0));
  EXPECT_FALSE(element_contains(element(e), {69, 59}, 0));
  Surface p;
  p.shape = SurfaceShape::polygon;
  p.points = {{0, 0}, {10, 0}, {0, 10}};
  EXPECT_TRUE(element_contains(element(p), {2, 2}, 0));
  EXPECT_FALSE(element_contains(element(p), {8, 8}, 0));
}

TEST(Geometry, TranslateThenBackIsIdentityForEveryKind) {
  Surface poly;
  poly.shape = SurfaceShape::polygon;
  poly.points = {{0, 0}, {10, 0}, {0, 10}};
  Group g;
  g.children = {element(Dot{1, 2, 1, 1}), element(poly)};
  for (Element e : {element(Dot{1, 2, 1, 1}), element(Line{}), element(poly), element(g)}) {
    const Element original = e;
    translate_element(e, 3.5, -2.25);
    EXPECT_NE(e, original);
    translate_element(e, -3.5, 2.25);
    EXPECT_EQ(e, original);
  }
}

TEST(Geometry, MapOntoNewBoundsGivesThoseBounds) {
  Surface ell;
  ell.shape = SurfaceShape::ellipse;
  ell.cx_mm = 10;
  ell.cy_mm = 10;
  ell.rx_mm = 5;
  ell.ry_mm = 3;
  Element e = element(ell);
  const RectMm to{0, 0, 40, 12};
  map_element(e, *element_bounds(e), to);
  const RectMm got = *element_bounds(e);
  EXPECT_NEAR(got.x0_mm, 0, 1e-12);
  EXPECT_NEAR(got.x1_mm, 40, 1e-12);
  EXPECT_NEAR(got.y1_mm, 12, 1e-12);
}

TEST(Geometry, SnapRoundsToTheStep) {
  EXPECT_DOUBLE_EQ(snap_mm(12.4, 5), 10);
  EXPECT_DOUBLE_EQ(snap_mm(12.6, 5), 15);
  EXPECT_DOUBLE_EQ(snap_mm(12.6, 0), 12.6);
}

TEST(Viewport, PixelAndMillimetreRoundTrip) {
  Viewport v(4.0);
  v.set_origin_px(100, 50);
  v.set_zoom(2.0);
  v.pan_px(7, -3);
  const Point2Px px = v.to_px({10, 20});
  EXPECT_FLOAT_EQ(px.x, 100 + 7 + 80);
  EXPECT_FLOAT_EQ(px.y, 50 - 3 + 160);
  const Point2Mm mm = v.to_mm(px);
  EXPECT_NEAR(mm.x_mm, 10, 1e-4);
  EXPECT_NEAR(mm.y_mm, 20, 1e-4);
}

TEST(Viewport, ZoomAtKeepsThePointUnderTheCursor) {
  Viewport v(4.0);
  v.set_origin_px(0, 0);
  const Point2Mm before = v.to_mm({200, 120});
  v.zoom_at(1.7, 200, 120);
  const Point2Mm after = v.to_mm({200, 120});
  EXPECT_NEAR(before.x_mm, after.x_mm, 1e-3);
  EXPECT_NEAR(before.y_mm, after.y_mm, 1e-3);
}

TEST(Viewport, GridStepIsAtLeastTheMinimumSpacing) {
  for (double ppm : {0.2, 1.0, 3.78, 10.0, 40.0}) {
    const double step = grid_step_mm(ppm, 8.0);
    EXPECT_GE(step * ppm, 8.0);
    EXPECT_LT(step * ppm, 8.0 * 2.5 + 1e-9);
  }
}

}  // namespace
}  // namespace vimg::editor

namespace vimg::editor {
namespace {

// A click on a polygon's outline within the slack hits it, as it does a rect's or an ellipse's;
// without slack only the inside counts (the player's contact test).
TEST(Geometry, APolygonIsHitOnItsOutlineWithinTheTolerance) {
  Surface s;
  s.shape = SurfaceShape::polygon;
  s.points = {{20, 20}, {60, 20}, {60, 60}, {20, 60}};
  Element e;
  e.body = s;
  EXPECT_TRUE(element_contains(e, {40, 60.4}, 0.5));
  EXPECT_TRUE(element_contains(e, {19.6, 40}, 0.5));
  EXPECT_FALSE(element_contains(e, {40, 61}, 0.5));
  EXPECT_FALSE(element_contains(e, {40, 60.4}, 0.0));
  EXPECT_TRUE(element_contains(e, {40, 40}, 0.0));
}

}  // namespace
}  // namespace vimg::editor
