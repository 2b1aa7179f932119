// Picture import: marching-squares outlines enclose exactly the set pixels, simplification stays
// within its tolerance, and pictures become SURFACE polygons by grey level (darker = stronger).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "png_fixture.hpp"
#include "primitives/geometry/hit_test.hpp"
#include "storage/image_io.hpp"
#include "storage/import/contours.hpp"
#include "storage/import/import.hpp"
#include "storage/import/rings.hpp"
#include "storage/png_codec.hpp"

namespace vimg {
namespace {

using import::Ring;

// Even-odd over all rings, as a SURFACE polygon fills.
bool inside_any(const std::vector<Ring>& rings, Vec2 p) {
  bool inside = false;
  for (const Ring& r : rings) inside ^= contains(Polygon{r}, p);
  return inside;
}

TEST(Contours, RandomMasksAreEnclosedExactlyAtEveryPixelCentre) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 12), h = 1 + static_cast<int>(rng() % 12);
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(w * h));
    for (auto& m : mask) m = rng() % 2;
    const std::vector<Ring> rings = import::trace_contours(mask, w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        EXPECT_EQ(inside_any(rings, {x + 0.5, y + 0.5}), mask[static_cast<std::size_t>(y * w + x)] != 0)
            << "trial " << trial << " pixel " << x << "," << y;
      }
    }
  }
}

TEST(Contours, OuterOutlinesAndHolesTurnOppositeWays) {
  // A 3x3 ring of set pixels: one outer outline and one hole.
  const std::vector<std::uint8_t> mask = {1, 1, 1, 1, 0, 1, 1, 1, 1};
  const std::vector<Ring> rings = import::trace_contours(mask, 3, 3);
  ASSERT_EQ(rings.size(), 2u);
  const double a0 = import::twice_signed_area(rings[0]), a1 = import::twice_signed_area(rings[1]);
  EXPECT_LT(std::min(a0, a1), 0.0);  // outer
  EXPECT_GT(std::max(a0, a1), 0.0);  // hole
}

TEST(Contours, SimplificationStaysWithinItsTolerance) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.3, 0.3);
  Ring circle;
  for (int i = 0; i < 500; ++i) {
    const double a = 2 * std::numbers::pi * i / 500;
    circle.push_back({50 + 40 * std::cos(a) + noise(rng), 50 + 40 * std::sin(a) + noise(rng)});
  }
  for (const double tolerance : {0.1, 0.5, 2.0}) {
    const Ring simple = import::simplify_ring(circle, tolerance);
    EXPECT_LT(simple.size(), circle.size());
    for (const Vec2& p : circle) {
      double best = 1e9;
      for (std::size_t i = 0; i < simple.size(); ++i) {
        best = std::min(best, distance_to_segment(p, simple[i], simple[(i + 1) % simple.size()]));
      }
      EXPECT_LE(best, tolerance + 1e-12);
    }
  }
}

// A square spiral one pixel wide, `turns` times round, in a mask of its size: one outline whose
// points wind in and out again, the shape that makes plain Douglas-Peucker split off a few points
// at a time.
std::vector<std::uint8_t> spiral_mask(int side) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
  int x0 = 0, y0 = 0, x1 = side - 1, y1 = side - 1;
  const auto set = [&](int x, int y) { mask[static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x)] = 1; };
  while (x0 + 2 <= x1 && y0 + 2 <= y1) {
    for (int x = x0; x <= x1; ++x) set(x, y0);
    for (int y = y0; y <= y1; ++y) set(x1, y);
    for (int x = x0; x <= x1; ++x) set(x, y1);
    for (int y = y0 + 2; y <= y1; ++y) set(x0, y);
    set(x0 + 1, y0 + 2);
    x0 += 2, y0 += 2, x1 -= 2, y1 -= 2;
  }
  return mask;
}

TEST(Contours, TracingVisitsEveryCrossingOnceWhateverTheShape) {
  for (const int side : {101, 401}) {
    const std::vector<std::uint8_t> mask = spiral_mask(side);
    std::size_t points = 0;
    const import::TraceStats stats = import::for_each_contour(mask, side, side, [&](Ring& ring) {
      points += ring.size();
      return true;
    });
    const std::size_t pairs = static_cast<std::size_t>(side + 2) * static_cast<std::size_t>(side + 2);
    EXPECT_EQ(stats.pairs_scanned, pairs);          // one look at each horizontal sample pair
    EXPECT_EQ(stats.crossings_visited, points);     // and each outline point made once
    EXPECT_LE(stats.crossings_visited, 2 * pairs);  // there are two crossings per sample at most
  }
}

TEST(Contours, TracingStopsWhenAskedAndTheOuterOutlineComesBeforeItsHoles) {
  const std::vector<std::uint8_t> mask = {1, 1, 1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 1, 0, 1};
  std::vector<double> areas;
  const import::TraceStats stats = import::for_each_contour(mask, 3, 5, [&](Ring& ring) {
    areas.push_back(import::twice_signed_area(ring));
    return areas.size() < 2;
  });
  EXPECT_TRUE(stats.stopped);
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_LT(areas[0], 0.0);  // the frame's outer outline ...
  EXPECT_GT(areas[1], 0.0);  // ... then its hole; the two pixels below are never traced
}

// A maze of one-pixel walls and corridors (odd side): the walls one outline, the corridors one
// hole, both turning at nearly every other pixel.
std::vector<std::uint8_t> maze_mask(int side) {
  const std::vector<bool> corridor = test::maze_corridors(side, 1);
  std::vector<std::uint8_t> mask(corridor.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = corridor[i] ? 0 : 1;
  return mask;
}

TEST(Contours, SimplificationCostIsLinearAndItsCountIsKnownBeforeTheRingEnds) {
  // The maze's corridors keep most of their corners: a few distance tests per point, and the count
  // of points kept grows while the ring arrives, so that a caller can refuse it long before its end.
  const int side = 801;
  const std::vector<std::uint8_t> mask = maze_mask(side);
  std::vector<Ring> rings = import::trace_contours(mask, side, side);
  ASSERT_EQ(rings.size(), 2u);
  const Ring& corridors = rings[0].size() > rings[1].size() ? rings[0] : rings[1];
  const std::size_t n = corridors.size();
  ASSERT_GT(n, 500000u);  // many windows
  import::SimplifyStats stats;
  import::RingSimplifier simplifier(0.1, &stats);
  std::size_t kept_at_half = 0;
  for (std::size_t i = 0; i < n; ++i) {
    simplifier.add(corridors[i]);
    if (i == n / 2) kept_at_half = simplifier.kept();
  }
  const Ring simple = simplifier.finish();
  EXPECT_GT(simple.size(), n / 4);
  EXPECT_LE(stats.distance_tests, 20 * n);  // log2 of the window, 14, at most per point
  EXPECT_GT(kept_at_half, simple.size() / 4);
}

TEST(Rings, BridgedRingsFillExactlyAsTheSeparateRingsEvenOdd) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    // An outer square and holes in random cells of a 10 x 10 grid, some holding islands.
    std::vector<Ring> rings = {{{0, 0}, {100, 0}, {100, 100}, {0, 100}}};
    for (int cell = 0; cell < 100; ++cell) {
      if (rng() % 3 != 0) continue;
      const double x = (cell % 10) * 10.0, y = (cell / 10) * 10.0;
      rings.push_back({{x + 2, y + 2}, {x + 2, y + 8}, {x + 8, y + 8}, {x + 8, y + 2}});
      if (rng() % 2 == 0) rings.push_back({{x + 4, y + 4}, {x + 6, y + 4}, {x + 6, y + 6}, {x + 4, y + 6}});
    }
    const Polygon bridged{import::bridge_rings(rings)};
    // Sample points off every ring edge (edges lie on whole numbers).
    for (int j = 0; j < 140; ++j) {
      const double y = 0.3183 + j * 0.7071;
      for (int i = 0; i < 140; ++i) {
        const double x = 0.2718 + i * 0.7071;
        // A plain comparison on this hot path (392 000 points); the assertion only for a difference.
        if (contains(bridged, {x, y}) != inside_any(rings, {x, y})) {
          ASSERT_EQ(contains(bridged, {x, y}), inside_any(rings, {x, y})) << "trial " << trial << " at " << x << "," << y;
        }
      }
    }
  }
}

std::vector<std::uint8_t> white(int w, int h, int channels) {
  return std::vector<std::uint8_t>(static_cast<std::size_t>(w * h * channels), 255);
}

void fill(std::vector<std::uint8_t>& px, int w, int channels, int x0, int y0, int x1, int y1, std::uint8_t value) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      for (int c = 0; c < std::min(channels, 3); ++c) px[static_cast<std::size_t>((y * w + x) * channels + c)] = value;
    }
  }
}

std::vector<const Surface*> surfaces(const Image& img) {
  std::vector<const Surface*> out;
  for (const Element& e : img.children) {
    for (const Element& c : std::get<Group>(e.body).children) out.push_back(&std::get<Surface>(c.body));
  }
  return out;
}

ImportOptions picture_options(double width_mm, int levels = 4) {
  ImportOptions o;
  o.width_mm = width_mm;
  o.levels = levels;
  return o;
}

TEST(PictureImport, BlackSquareOnWhiteIsOneSurfaceCoveringIt) {
  const int w = 40, h = 30;
  std::vector<std::uint8_t> px = white(w, h, 1);
  fill(px, w, 1, 10, 8, 25, 23, 0);  // 15 x 15 px at (10, 8)
  const double mm_per_px = 0.5;
  const ImportResult r = import_picture(test::make_png(w, h, 1, px), "sq.png", picture_options(w * mm_per_px));
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.image->height_mm, h * mm_per_px);
  const auto all = surfaces(*r.image);
  ASSERT_EQ(all.size(), 1u);
  const Surface& s = *all[0];
  EXPECT_DOUBLE_EQ(s.gain, 1.0);
  double min_x = 1e9, min_y = 1e9, max_x = -1e9, max_y = -1e9;
  for (const Point2Mm& p : s.points) {
    min_x = std::min(min_x, p.x_mm), max_x = std::max(max_x, p.x_mm);
    min_y = std::min(min_y, p.y_mm), max_y = std::max(max_y, p.y_mm);
  }
  EXPECT_NEAR(min_x, 10 * mm_per_px, mm_per_px);
  EXPECT_NEAR(max_x, 25 * mm_per_px, mm_per_px);
  EXPECT_NEAR(min_y, 8 * mm_per_px, mm_per_px);
  EXPECT_NEAR(max_y, 23 * mm_per_px, mm_per_px);
  // Every pixel centre of the square is covered and every other one is not.
  Polygon poly;
  for (const Point2Mm& p : s.points) poly.vertices.push_back({p.x_mm, p.y_mm});
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool in_square = x >= 10 && x < 25 && y >= 8 && y < 23;
      EXPECT_EQ(contains(poly, {(x + 0.5) * mm_per_px, (y + 0.5) * mm_per_px}), in_square) << x << "," << y;
    }
  }
}

TEST(PictureImport, HolesAreKeptAndLevelsFollowDarkness) {
  const int w = 30, h = 30;
  std::vector<std::uint8_t> px = white(w, h, 3);
  fill(px, w, 3, 2, 2, 28, 28, 0);      // black frame ...
  fill(px, w, 3, 8, 8, 22, 22, 255);    // ... with a white hole ...
  fill(px, w, 3, 12, 12, 18, 18, 128);  // ... holding a mid-grey island
  const ImportResult r = import_picture(test::make_png(w, h, 3, px), "frame.png", picture_options(30.0, 4));
  ASSERT_TRUE(r.ok());
  const auto all = surfaces(*r.image);
  ASSERT_EQ(all.size(), 2u);
  const Surface* grey = all[0]->gain < all[1]->gain ? all[0] : all[1];
  const Surface* black = all[0]->gain < all[1]->gain ? all[1] : all[0];
  EXPECT_DOUBLE_EQ(black->gain, 1.0);
  EXPECT_DOUBLE_EQ(grey->gain, 0.5);  // 128/255 darkness ~0.5: level 2 of 4
  Polygon frame;
  for (const Point2Mm& p : black->points) frame.vertices.push_back({p.x_mm, p.y_mm});
  EXPECT_TRUE(contains(frame, {4.5, 4.5}));
  EXPECT_FALSE(contains(frame, {10.5, 10.5}));  // the hole
  EXPECT_FALSE(contains(frame, {15.5, 15.5}));  // the island is not part of the frame
  EXPECT_TRUE(parse_image_xml(write_image_xml(*r.image), "frame.vimg").ok());
}

TEST(PictureImport, TransparentPixelsAreWhite) {
  std::vector<std::uint8_t> px(static_cast<std::size_t>(10 * 10 * 4), 0);  // black, fully transparent
  const ImportResult r = import_picture(test::make_png(10, 10, 4, px), "clear.png", picture_options(10.0));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.image->children.empty());
}

TEST(PictureImport, BadOptionsAndDamagedFilesAreErrors) {
  const std::string png = test::make_png(4, 4, 1, white(4, 4, 1));
  EXPECT_FALSE(import_picture(png, "p.png", {}).ok());  // no width
  EXPECT_FALSE(import_picture(png, "p.png", picture_options(10.0, 0)).ok());
  EXPECT_FALSE(import_picture(png, "p.png", picture_options(10.0, kMaxPictureLevels + 1)).ok());
  EXPECT_FALSE(import_picture(png.substr(0, png.size() - 20), "p.png", picture_options(10.0)).ok());
  const ImportResult tall = import_picture(test::make_png(1, 100, 1, white(1, 100, 1)), "p.png", picture_options(200.0));
  ASSERT_FALSE(tall.ok());
  EXPECT_NE(tall.diagnostics.back().to_string().find("p.png: error:"), std::string::npos);
}

// A picture another project made: the Adwaita folder icon (48 x 48 RGBA, antialiased edges,
// transparency; tests/import/data/README.md). At 1 mm per pixel, every pixel centre lies in exactly
// the one SURFACE of its level (darkness over white, docs/import.md), or in none at level 0.
TEST(PictureImport, AForeignIconPutsEveryPixelInTheSurfaceOfItsLevel) {
  const std::filesystem::path file = VIMG_SOURCE_DIR "/tests/import/data/adwaita-folder-48.png";
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const DecodedPng png = decode_png_rgba(bytes, 1e6);
  ASSERT_TRUE(png.error.empty()) << png.error;
  const int levels = 4;
  const ImportResult r = import_file(file, picture_options(png.width, levels));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(parse_image_xml(write_image_xml(*r.image), "folder.vimg").ok());
  const auto all = surfaces(*r.image);
  ASSERT_GE(all.size(), 2u);
  std::vector<Polygon> polygons;
  for (const Surface* s : all) {
    Polygon poly;
    for (const Point2Mm& p : s->points) poly.vertices.push_back({p.x_mm, p.y_mm});
    polygons.push_back(poly);
  }
  int covered = 0;
  for (int y = 0; y < png.height; ++y) {
    for (int x = 0; x < png.width; ++x) {
      const std::uint8_t* p = png.rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(png.width) + static_cast<std::size_t>(x)) * 4;
      const double darkness = (1.0 - (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0) * (p[3] / 255.0);
      const long level = std::lround(darkness * levels);
      std::vector<double> gains;
      for (std::size_t i = 0; i < all.size(); ++i) {
        if (contains(polygons[i], {x + 0.5, y + 0.5})) gains.push_back(all[i]->gain);
      }
      if (level == 0) {
        EXPECT_TRUE(gains.empty()) << x << "," << y;
      } else {
        ASSERT_EQ(gains.size(), 1u) << x << "," << y;
        EXPECT_DOUBLE_EQ(gains[0], static_cast<double>(level) / levels) << x << "," << y;
        ++covered;
      }
    }
  }
  EXPECT_GT(covered, 500);  // the folder covers much of the icon
}

TEST(PictureImport, APngThatHoldsAVibroimageIsOpenedNotImported) {
  const std::filesystem::path file = VIMG_SOURCE_DIR "/assets/examples/smiley.png";
  const ImportResult r = import_file(file, picture_options(50.0));
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.opened_vibroimage);
  EXPECT_EQ(*r.image, *load_image_file(file).image);
}

}  // namespace
}  // namespace vimg
