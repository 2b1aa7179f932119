// The PNG picture (docs/format-png.md "PNG"): polygons filled by scanlines in time that grows with
// points plus rows (counted, never timed), with the anti-aliasing and even-odd rule of the other
// shapes, and any finite coordinates drawn without overflow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "storage/palette.hpp"
#include "storage/picture.hpp"
#include "storage/picture_painter.hpp"

namespace vimg {
namespace {

Image canvas(double w_mm, double h_mm) {
  Image image;
  image.width_mm = w_mm;
  image.height_mm = h_mm;
  return image;
}

void add_surface(Image& image, Surface s) {
  s.pattern = SurfacePattern::square;
  s.period_mm = 1e6;  // one stripe wider than any canvas: a uniform fill at the square's high level
  Element e;
  e.body = s;
  image.children.push_back(e);
}

Surface polygon(std::vector<Point2Mm> points) {
  Surface s;
  s.shape = SurfaceShape::polygon;
  s.points = std::move(points);
  return s;
}

std::vector<Point2Mm> circle(double cx, double cy, double r, std::size_t n) {
  std::vector<Point2Mm> points;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    points.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return points;
}

// How much a pixel differs from the white background, summed over the channels (0..765).
int ink(const RgbRaster& r, int x, int y) {
  const std::uint8_t* p = r.pixel(x, y);
  return 765 - p[0] - p[1] - p[2];
}

double total_ink(const RgbRaster& r) {
  double sum = 0;
  for (int y = 0; y < r.height; ++y) {
    for (int x = 0; x < r.width; ++x) sum += ink(r, x, y);
  }
  return sum;
}

RgbRaster draw(const Image& image, double scale, PictureWork* work = nullptr) {
  RgbRaster raster;
  const auto error = draw_picture(image, scale, raster, work);
  EXPECT_FALSE(error.has_value()) << *error;
  return raster;
}

TEST(Picture, PolygonWorkGrowsWithPointsPlusRowsNotTheirProduct) {
  // A 2000-point circle on a 200 x 200 px canvas. Testing every edge at every pixel costs
  // 40 000 x 2000 edge visits; a scanline fill visits each edge once per row it spans.
  Image image = canvas(20, 20);
  const std::size_t points = 2000;
  add_surface(image, polygon(circle(10, 10, 9, points)));
  PictureWork work;
  draw(image, 10.0, &work);
  const std::uint64_t rows = 200;
  EXPECT_LE(work.edge_steps, 4 * (points + rows)) << "edge visits";
  EXPECT_LE(work.pixels, 2u * 200u * 200u) << "pixels visited";
}

TEST(Picture, PolygonWorkIsBoundedByTheEdgesHeights) {
  // 1000 points zigzagging over the full height: every edge spans every row, the worst case.
  Image image = canvas(20, 20);
  std::vector<Point2Mm> zigzag;
  const std::size_t points = 1000;
  for (std::size_t i = 0; i < points; ++i) {
    zigzag.push_back({20.0 * static_cast<double>(i) / points, i % 2 == 0 ? 0.0 : 20.0});
  }
  add_surface(image, polygon(zigzag));
  PictureWork work;
  draw(image, 10.0, &work);
  EXPECT_LE(work.edge_steps, points * (200 + 2));
}

TEST(Picture, PolygonCoversLikeTheSameRectangle) {
  // Edges half way through pixels: both shapes give those pixels half coverage.
  Surface rect;
  rect.shape = SurfaceShape::rect;
  rect.x_mm = 5.05;
  rect.y_mm = 3.05;
  rect.width_mm = 20.0;
  rect.height_mm = 10.0;
  Image a = canvas(30, 20);
  add_surface(a, rect);
  Image b = canvas(30, 20);
  add_surface(b, polygon({{5.05, 3.05}, {25.05, 3.05}, {25.05, 13.05}, {5.05, 13.05}}));
  const RgbRaster ra = draw(a, 10.0);
  const RgbRaster rb = draw(b, 10.0);
  const int full = ink(ra, 150, 80);
  ASSERT_GT(full, 100);
  EXPECT_EQ(ink(rb, 150, 80), full);
  EXPECT_EQ(ink(rb, 40, 80), 0) << "outside";
  EXPECT_NEAR(ink(rb, 50, 80), full / 2, 3) << "left edge at x = 50.5 px: half covered";
  EXPECT_NEAR(ink(rb, 150, 130), full / 2, 3) << "bottom edge at y = 130.5 px: half covered";
  EXPECT_NEAR(total_ink(rb), total_ink(ra), 0.002 * total_ink(ra));
}

TEST(Picture, DiagonalEdgesAreAntiAliasedAndCoverTheirArea) {
  // A diamond of diagonals 16 mm: area 128 mm^2 = 12 800 px^2 at 10 px/mm.
  Image image = canvas(20, 20);
  add_surface(image, polygon({{10, 2}, {18, 10}, {10, 18}, {2, 10}}));
  const RgbRaster r = draw(image, 10.0);
  const int full = ink(r, 100, 100);
  ASSERT_GT(full, 100);
  EXPECT_NEAR(total_ink(r) / full, 12800.0, 0.01 * 12800.0);
  int intermediate = 0;
  for (int x = 0; x < 200; ++x) {
    const int v = ink(r, x, 60);
    intermediate += v > full / 10 && v < full * 9 / 10;
  }
  EXPECT_GE(intermediate, 2) << "the two edges crossing row 60 are anti-aliased";
  EXPECT_LE(intermediate, 6);
}

TEST(Picture, SelfIntersectingPolygonsUseTheEvenOddRule) {
  // A pentagram: its points are inside, its centre pentagon is crossed twice and stays empty.
  Image image = canvas(40, 40);
  std::vector<Point2Mm> star;
  for (int i = 0; i < 5; ++i) {
    const double a = -std::numbers::pi / 2 + 4.0 * std::numbers::pi * i / 5.0;
    star.push_back({20 + 18 * std::cos(a), 20 + 18 * std::sin(a)});
  }
  add_surface(image, polygon(star));
  const RgbRaster r = draw(image, 10.0);
  EXPECT_EQ(ink(r, 200, 200), 0) << "centre";
  EXPECT_GT(ink(r, 200, 40), 100) << "top point";
}

TEST(Picture, HugeFiniteCoordinatesNeitherOverflowNorHang) {
  const double big = std::numeric_limits<double>::max();
  Image image = canvas(20, 20);
  add_surface(image, polygon({{-big, -big}, {big, -big}, {big, big}, {-big, big}}));  // covers everything
  add_surface(image, polygon({{1e300, 5}, {-1e300, 6}, {3, 1e300}}));
  add_surface(image, polygon({{5, 5}, {5, 5}, {5, 5}}));  // no area
  Line line;
  line.x1_mm = -1e308;
  line.y1_mm = -1e308;
  line.x2_mm = 1e308;
  line.y2_mm = 1e308;
  Element e;
  e.body = line;
  image.children.push_back(e);
  Element d;
  d.body = Dot{1e308, -1e308, 1e308, 1.0};
  image.children.push_back(d);
  d.body = Dot{10, 10, 1e77, 1.0};  // its inner run spans 1e78 px each way (found by the XML fuzzer)
  image.children.push_back(d);
  PictureWork work;
  const RgbRaster r = draw(image, 10.0, &work);
  EXPECT_GT(ink(r, 100, 100), 0);
  EXPECT_LE(work.edge_steps, 20u * 200u);
  EXPECT_LE(work.pixels, image.children.size() * 200u * 200u) << "each shape draws at most the canvas";
}

TEST(Picture, AnInnerRunFarOutsideTheRowIsClampedToIt) {
  int i0 = 0, i1 = 0;
  picture_detail::inner_run(-1.7e78, 1.7e78, 3, 99, i0, i1);
  EXPECT_EQ(i0, 3);
  EXPECT_EQ(i1, 99);
  picture_detail::inner_run(-1e300, 50.2, 3, 99, i0, i1);
  EXPECT_EQ(i0, 3);
  EXPECT_EQ(i1, 49);
  picture_detail::inner_run(1e300, 2e300, 3, 99, i0, i1);
  EXPECT_GT(i0, i1) << "none";
}

// One look (docs/format-png.md, storage/palette.hpp): a surface's stripes run vertically on every
// shape; its opacity at x follows palette::surface_opacity, so a fully opaque stripe is exactly
// the palette's surface colour and the picture repeats with the period along x, never along y.
TEST(Picture, SurfaceStripesRunVerticallyOnEveryShape) {
  for (const SurfaceShape shape : {SurfaceShape::rect, SurfaceShape::ellipse, SurfaceShape::polygon}) {
    Image image = canvas(40, 40);
    Surface s;
    s.shape = shape;
    s.x_mm = 5;
    s.y_mm = 5;
    s.width_mm = 30;
    s.height_mm = 30;
    s.cx_mm = 20;
    s.cy_mm = 20;
    s.rx_mm = 15;
    s.ry_mm = 15;
    s.points = {{5, 5}, {35, 5}, {35, 35}, {5, 35}};
    s.pattern = SurfacePattern::sine;
    s.period_mm = 4;  // 16 px at 4 px/mm
    s.gain = 1.0;
    Element e;
    e.body = s;
    image.children.push_back(e);
    const RgbRaster r = draw(image, 4.0);
    int varying_columns = 0;
    for (int x = 64; x < 96; ++x) {  // well inside every shape: x and y in [16, 24] mm
      for (int y = 64; y < 96; ++y) {
        ASSERT_EQ(ink(r, x, y), ink(r, x, 64)) << "shape " << static_cast<int>(shape) << " column " << x << " row " << y;
      }
      EXPECT_NEAR(ink(r, x, 80), ink(r, x + 16, 80), 3) << "one period along x";
      const double expected = palette::surface_opacity(s, (x + 0.5) / 4.0);
      const double full = 765 - palette::kSurface.r - palette::kSurface.g - palette::kSurface.b;
      EXPECT_NEAR(ink(r, x, 80), expected * full, 4) << "column " << x;
      if (std::abs(ink(r, x, 80) - ink(r, 64, 80)) > 20) ++varying_columns;
    }
    EXPECT_GT(varying_columns, 8) << "the stripes vary across x";
  }
}

TEST(Picture, AnOpaqueSurfaceIsExactlyThePaletteColour) {
  Image image = canvas(20, 20);
  Surface s;
  s.x_mm = 2;
  s.y_mm = 2;
  s.width_mm = 16;
  s.height_mm = 16;
  s.gain = 1.0;
  add_surface(image, s);  // square pattern, one stripe: opacity 1 everywhere
  const RgbRaster r = draw(image, 4.0);
  const std::uint8_t* p = r.pixel(40, 40);
  EXPECT_EQ(p[0], palette::kSurface.r);
  EXPECT_EQ(p[1], palette::kSurface.g);
  EXPECT_EQ(p[2], palette::kSurface.b);
  const std::uint8_t* outside = r.pixel(2, 2);
  EXPECT_EQ(outside[0], palette::kBackground.r);
}

}  // namespace
}  // namespace vimg
