// Transforms, units, viewBox fitting and curve flattening, against their definitions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "primitives/geometry/hit_test.hpp"
#include "storage/import/svg_attributes.hpp"
#include "storage/import/svg_flatten.hpp"
#include "storage/import/svg_shapes.hpp"
#include "storage/limits.hpp"
#include "storage/import/svg_transform.hpp"

namespace vimg::svg {
namespace {

Affine parsed(std::string_view t) {
  const TransformParse p = parse_transform(t);
  EXPECT_TRUE(p.error.empty()) << t << ": " << p.error;
  return p.transform;
}

void expect_point(Vec2 p, double x, double y, double tolerance = 1e-9) {
  EXPECT_NEAR(p.x, x, tolerance);
  EXPECT_NEAR(p.y, y, tolerance);
}

TEST(SvgTransform, EachKindMapsPointsAsDefined) {
  expect_point(parsed("translate(3, 4)").apply({1, 1}), 4, 5);
  expect_point(parsed("translate(3)").apply({1, 1}), 4, 1);
  expect_point(parsed("scale(2)").apply({1, 3}), 2, 6);
  expect_point(parsed("scale(2 -1)").apply({1, 3}), 2, -3);
  expect_point(parsed("rotate(90)").apply({1, 0}), 0, 1);  // y down: +90 turns x onto y
  expect_point(parsed("rotate(90 10 10)").apply({10, 10}), 10, 10);
  expect_point(parsed("rotate(90 10 10)").apply({11, 10}), 10, 11);
  expect_point(parsed("skewX(45)").apply({0, 2}), 2, 2);
  expect_point(parsed("skewY(45)").apply({2, 0}), 2, 2);
  expect_point(parsed("matrix(1 2 3 4 5 6)").apply({1, 1}), 1 + 3 + 5, 2 + 4 + 6);
}

TEST(SvgTransform, AListAppliesRightToLeftAndNests) {
  // translate then scale: the point is scaled first.
  expect_point(parsed("translate(10,0) scale(2)").apply({1, 1}), 12, 2);
  expect_point(parsed("scale(2),translate(10,0)").apply({1, 1}), 22, 2);
  const Affine outer = parsed("translate(5 5)"), inner = parsed("rotate(180)");
  expect_point((outer * inner).apply({1, 0}), 4, 5);
}

TEST(SvgTransform, BadListsAreErrors) {
  for (const char* bad : {"rotate(1 2)", "scale()", "translate(1 2 3)", "matrix(1 2 3)", "spin(3)", "scale(2",
                          "translate(1e999)"}) {
    EXPECT_FALSE(parse_transform(bad).error.empty()) << bad;
  }
  EXPECT_TRUE(parse_transform("").error.empty());
}

TEST(SvgUnits, LengthsConvertAtNinetySixPixelsPerInch) {
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("10mm")), 10.0);
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("1cm")), 10.0);
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("1in")), 25.4);
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("72pt")), 25.4);
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("6pc")), 25.4);
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("96px")), 25.4);
  EXPECT_DOUBLE_EQ(*length_mm(*parse_length("96")), 25.4);
  EXPECT_FALSE(length_mm(*parse_length("50%")));
  EXPECT_FALSE(parse_length("12 apples"));
  EXPECT_FALSE(parse_length("mm"));
}

TEST(SvgUnits, ViewBoxFitFollowsPreserveAspectRatio) {
  const ViewBox box{0, 0, 100, 50};
  // Viewport 100 x 100: meet scales by 1 and centres vertically (25 above).
  expect_point(view_box_transform(box, 100, 100, "")->apply({0, 0}), 0, 25);
  expect_point(view_box_transform(box, 100, 100, "xMinYMin meet")->apply({0, 0}), 0, 0);
  expect_point(view_box_transform(box, 100, 100, "xMaxYMax")->apply({100, 50}), 100, 100);
  expect_point(view_box_transform(box, 100, 100, "xMidYMid slice")->apply({50, 25}), 50, 50);
  expect_point(view_box_transform(box, 100, 100, "xMidYMid slice")->apply({0, 0}), -50, 0);
  expect_point(view_box_transform(box, 100, 100, "none")->apply({100, 50}), 100, 100);
  expect_point(view_box_transform(ViewBox{10, 20, 10, 10}, 5, 5, "")->apply({20, 30}), 5, 5);
  EXPECT_FALSE(view_box_transform(box, 100, 100, "xMidYMiddle"));
  EXPECT_FALSE(view_box_transform(box, 100, 100, "xMidYMid cover"));
}

TEST(SvgStyle, StyleAttributeWinsAndPropertiesInherit) {
  std::vector<std::string> problems;
  const Style root = cascade(Style{}, declared_properties({{"fill", "red"}, {"stroke", "blue"}}, "fill:none"), problems);
  EXPECT_FALSE(root.fill);
  EXPECT_TRUE(root.stroke);
  const Style child = cascade(root, declared_properties({{"stroke-width", "2mm"}}, ""), problems);
  EXPECT_FALSE(child.fill);
  EXPECT_NEAR(child.stroke_width, 2.0 * 96 / 25.4, 1e-12);
  const Style gradient = cascade(child, declared_properties({}, "fill: url(#g) ; display:none"), problems);
  EXPECT_TRUE(gradient.fill && gradient.fill_is_server);
  EXPECT_FALSE(gradient.displayed);
  EXPECT_TRUE(cascade(gradient, declared_properties({}, ""), problems).displayed);  // display is not inherited
  EXPECT_TRUE(problems.empty());
  cascade(root, declared_properties({{"stroke-width", "thick"}}, ""), problems);
  EXPECT_EQ(problems.size(), 1u);
}

// The largest distance from points of the cubic to the polyline.
double deviation(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 p3, const std::vector<Vec2>& polyline) {
  double worst = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0, u = 1.0 - t;
    const Vec2 q = p0 * (u * u * u) + c1 * (3 * u * u * t) + c2 * (3 * u * t * t) + p3 * (t * t * t);
    double best = 1e300;
    for (std::size_t k = 1; k < polyline.size(); ++k) best = std::min(best, distance_to_segment(q, polyline[k - 1], polyline[k]));
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(SvgFlatten, RandomCubicsStayWithinTheToleranceAfterTheTransform) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  const Affine to_mm = parsed("scale(0.5) rotate(30) skewX(10)");
  for (int trial = 0; trial < 50; ++trial) {
    Subpath s;
    s.start = {coordinate(rng), coordinate(rng)};
    const PathSegment c{PathSegment::Kind::cubic, {coordinate(rng), coordinate(rng)}, {coordinate(rng), coordinate(rng)},
                        {coordinate(rng), coordinate(rng)}};
    s.segments.push_back(c);
    std::vector<Vec2> points;
    ASSERT_TRUE(flatten_subpath(s, to_mm, 0.05, 100000, points));
    EXPECT_LE(deviation(to_mm.apply(s.start), to_mm.apply(c.c1), to_mm.apply(c.c2), to_mm.apply(c.end), points), 0.05 + 1e-9);
    expect_point(points.front(), to_mm.apply(s.start).x, to_mm.apply(s.start).y);
    expect_point(points.back(), to_mm.apply(c.end).x, to_mm.apply(c.end).y);
    // Adaptive: far fewer points than a uniform split at the same tolerance would need.
    EXPECT_LT(points.size(), 400u);
  }
}

TEST(SvgFlatten, PointBudgetIsEnforced) {
  Subpath s;
  s.segments.push_back({PathSegment::Kind::cubic, {0, 100}, {100, 100}, {100, 0}});
  std::vector<Vec2> points;
  EXPECT_FALSE(flatten_subpath(s, Affine{}, 1e-6, 10, points));
  EXPECT_LE(points.size(), 10u);
}

TEST(SvgShapes, AShapeStopsAtTheImportsBudgetsAsItProducesPointsAndLines) {
  // A stroked curve some 3e6 mm across: tens of thousands of points and LINEs within 0.05 mm.
  ShapeGeometry g;
  Subpath curve;
  curve.segments.push_back({PathSegment::Kind::cubic, {3e6, 3e6}, {-3e6, 3e6}, {1, 0}});
  g.subpaths.push_back(curve);
  ShapeSettings settings;
  settings.style.fill = false;
  settings.style.stroke = true;
  settings.max_points = 100'000;
  settings.primitives_left = 100;
  const ShapeOutput lines = convert_shape(g, settings);
  EXPECT_TRUE(lines.over_primitives);
  EXPECT_EQ(lines.primitives.size(), 100u);  // not one LINE more than the import may still hold
  settings.primitives_left = static_cast<std::size_t>(-1);
  settings.points_left = 1000;
  const ShapeOutput points = convert_shape(g, settings);
  EXPECT_LE(points.points, 1000u);
  EXPECT_TRUE(points.primitives.empty());
  const std::string limit = std::to_string(kMaxImportPoints);
  EXPECT_EQ(points.error, "the drawing's curves and outlines flatten to more than " + limit + " points in all (limit " + limit + ")");
}

}  // namespace
}  // namespace vimg::svg
