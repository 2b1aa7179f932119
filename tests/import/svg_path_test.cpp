// SVG path data: every command, relative and absolute, implicit repeats, the number syntax and the
// arc flags, against the geometry the SVG specification defines.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "storage/import/svg_path.hpp"

namespace vimg::svg {
namespace {

PathParse parse(std::string_view d) { return parse_path_data(d, 100000); }

void expect_point(Vec2 p, double x, double y) {
  EXPECT_NEAR(p.x, x, 1e-9);
  EXPECT_NEAR(p.y, y, 1e-9);
}

TEST(SvgPath, AbsoluteAndRelativeLinesWithImplicitRepeats) {
  const PathParse p = parse("M10 20 30 40 l5 5 5 5 H0 v-10 h2 V1 z");
  ASSERT_TRUE(p.error.empty()) << p.error;
  ASSERT_EQ(p.subpaths.size(), 1u);
  const Subpath& s = p.subpaths[0];
  expect_point(s.start, 10, 20);
  ASSERT_EQ(s.segments.size(), 8u);  // implicit L, l, l, H, v, h, V, closing line
  expect_point(s.segments[0].end, 30, 40);
  expect_point(s.segments[1].end, 35, 45);
  expect_point(s.segments[2].end, 40, 50);
  expect_point(s.segments[3].end, 0, 50);
  expect_point(s.segments[4].end, 0, 40);
  expect_point(s.segments[5].end, 2, 40);
  expect_point(s.segments[6].end, 2, 1);
  expect_point(s.segments[7].end, 10, 20);
  EXPECT_TRUE(s.closed);
}

TEST(SvgPath, RelativeMovetoRepeatsAreRelativeLinetos) {
  const PathParse p = parse("m1 1 2 0 0 2");
  ASSERT_EQ(p.subpaths.size(), 1u);
  expect_point(p.subpaths[0].segments[0].end, 3, 1);
  expect_point(p.subpaths[0].segments[1].end, 3, 3);
}

TEST(SvgPath, NumberSyntax) {
  const PathParse p = parse("M.5.5L1e-3-2E+1,-.5-.5l+1 0");
  ASSERT_TRUE(p.error.empty()) << p.error;
  const Subpath& s = p.subpaths[0];
  expect_point(s.start, 0.5, 0.5);
  expect_point(s.segments[0].end, 0.001, -20);
  expect_point(s.segments[1].end, -0.5, -0.5);
  expect_point(s.segments[2].end, 0.5, -0.5);
}

TEST(SvgPath, ArcFlagsWithoutSeparators) {
  // rx ry rotation large sweep x y, flags packed: "0 01.5.5" is large=0 sweep=1 x=.5 y=.5 (relative).
  const PathParse p = parse("M0 0a.5.5 0 01.5.5");
  ASSERT_TRUE(p.error.empty()) << p.error;
  ASSERT_FALSE(p.subpaths[0].segments.empty());
  expect_point(p.subpaths[0].segments.back().end, 0.5, 0.5);
}

TEST(SvgPath, ArcPointsLieOnTheCircle) {
  // A half circle of radius 5 centred at (5, 0), sweep flag 1 (positive angle, clockwise on screen).
  const PathParse p = parse("M0 0 A5 5 0 0 1 10 0");
  ASSERT_TRUE(p.error.empty());
  const auto& segs = p.subpaths[0].segments;
  ASSERT_EQ(segs.size(), 4u);  // 180 degrees: four cubics of 45
  Vec2 start = p.subpaths[0].start;
  for (const PathSegment& s : segs) {
    ASSERT_EQ(s.kind, PathSegment::Kind::cubic);
    for (double t = 0.0; t <= 1.0; t += 0.05) {
      const double u = 1.0 - t;
      const Vec2 q = start * (u * u * u) + s.c1 * (3 * u * u * t) + s.c2 * (3 * u * t * t) + s.end * (t * t * t);
      EXPECT_NEAR(norm(q - Vec2{5, 0}), 5.0, 5.0 * 5e-6);
      EXPECT_LE(q.y, 1e-9);  // sweep 1 from (0,0) to (10,0) passes through y < 0 (the top on screen)
    }
    start = s.end;
  }
  expect_point(segs[1].end, 5, -5);
}

TEST(SvgPath, LargeArcFlagChoosesTheLongWay) {
  const PathParse small = parse("M0 0 A10 10 0 0 1 10 0");
  const PathParse large = parse("M0 0 A10 10 0 1 1 10 0");
  EXPECT_LT(small.subpaths[0].segments.size(), large.subpaths[0].segments.size());
}

TEST(SvgPath, ArcWithTooSmallRadiiIsScaledUpAndZeroRadiusIsALine) {
  const PathParse scaled = parse("M0 0 A1 1 0 0 1 10 0");  // radius grows to 5
  expect_point(scaled.subpaths[0].segments[1].end, 5, -5);
  const PathParse line = parse("M0 0 A0 3 0 0 1 10 0");
  ASSERT_EQ(line.subpaths[0].segments.size(), 1u);
  EXPECT_EQ(line.subpaths[0].segments[0].kind, PathSegment::Kind::line);
}

TEST(SvgPath, SmoothCubicReflectsThePreviousControlPoint) {
  const PathParse p = parse("M0 0 C0 10 10 10 10 0 S20 -10 20 0");
  const auto& segs = p.subpaths[0].segments;
  ASSERT_EQ(segs.size(), 2u);
  expect_point(segs[1].c1, 10, -10);  // reflection of (10,10) about (10,0)
  const PathParse alone = parse("M0 0 S5 5 10 0");  // no previous cubic: c1 is the current point
  expect_point(alone.subpaths[0].segments[0].c1, 0, 0);
}

TEST(SvgPath, QuadraticsBecomeExactCubicsAndTReflects) {
  const PathParse p = parse("M0 0 Q5 10 10 0 T20 0");
  const auto& segs = p.subpaths[0].segments;
  ASSERT_EQ(segs.size(), 2u);
  expect_point(segs[0].c1, 5.0 * 2 / 3, 10.0 * 2 / 3);
  expect_point(segs[0].c2, 10 + (5 - 10) * 2.0 / 3, 10.0 * 2 / 3);
  // T's control point is (15, -10): c1 = p0 + 2/3 (q - p0).
  expect_point(segs[1].c1, 10 + 5.0 * 2 / 3, -10.0 * 2 / 3);
}

TEST(SvgPath, DrawingAfterCloseStartsAtTheSubpathStart) {
  const PathParse p = parse("M5 5 h10 v10 z l1 1");
  ASSERT_EQ(p.subpaths.size(), 2u);
  expect_point(p.subpaths[1].start, 5, 5);
  expect_point(p.subpaths[1].segments[0].end, 6, 6);
}

TEST(SvgPath, ErrorsKeepWhatCameBefore) {
  const PathParse bad = parse("M0 0 L10 10 L20 x");
  EXPECT_FALSE(bad.error.empty());
  EXPECT_EQ(bad.error_offset, 16u);
  ASSERT_EQ(bad.subpaths.size(), 1u);
  EXPECT_EQ(bad.subpaths[0].segments.size(), 1u);
  EXPECT_FALSE(parse("L10 10").error.empty());
  EXPECT_FALSE(parse("M0 0 X1").error.empty());
  EXPECT_FALSE(parse("M0 0 A1 1 0 2 1 5 5").error.empty());  // flag must be 0 or 1
  EXPECT_FALSE(parse("M1e999 0").error.empty());              // not finite
  EXPECT_FALSE(parse("M0 0 Linf 0").error.empty());
  EXPECT_TRUE(parse("").error.empty());
}

TEST(SvgPath, SegmentLimitIsEnforced) {
  std::string d = "M0 0";
  for (int i = 0; i < 20; ++i) d += " L" + std::to_string(i) + " 1";
  EXPECT_TRUE(parse_path_data(d, 20).error.empty());
  const PathParse over = parse_path_data(d, 19);
  EXPECT_NE(over.error.find("limit 19"), std::string::npos) << over.error;
}

}  // namespace
}  // namespace vimg::svg
