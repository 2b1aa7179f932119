// Pictures built to hurt the importer (issue 23, "Imports built to hurt"): each is imported in a
// child process under an address-space and a CPU-time cap (bounded_child.hpp), and must end there
// with its limit named. Nothing is timed. Also the PNG pixel limits, on import and on export.
#include <gtest/gtest.h>
#include <zlib.h>

#include <array>
#include <random>
#include <string>
#include <vector>

#include "../import/png_fixture.hpp"
#include "bounded_child.hpp"
#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/limits.hpp"
#include "storage/picture.hpp"
#include "storage/png_codec.hpp"

namespace vimg {
namespace {

constexpr std::size_t kCapMiB = std::size_t{1} << 20;

std::string errors_of(const ImportResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) out += d.to_string() + "\n";
  }
  return out;
}

ImportOptions at_one_mm_per_pixel(int width_px) {
  ImportOptions options;
  options.width_mm = width_px;
  return options;
}

// A 16 x 16 grey picture (its rows need 16 x 17 = 272 bytes) whose image data is 1 GiB of zeros,
// deflated (about 1 MB).
std::string inflate_bomb_png() {
  std::string z(2 * kCapMiB, '\0');
  z_stream s{};
  deflateInit(&s, 9);
  const std::vector<Bytef> zeros(kCapMiB, 0);
  std::size_t written = 0;
  for (int mib = 0; mib < 1024; ++mib) {
    s.next_in = const_cast<Bytef*>(zeros.data());
    s.avail_in = static_cast<uInt>(zeros.size());
    do {
      if (z.size() - written < 65536) z.resize(z.size() * 2);
      s.next_out = reinterpret_cast<Bytef*>(z.data() + written);
      s.avail_out = static_cast<uInt>(z.size() - written);
      deflate(&s, mib == 1023 ? Z_FINISH : Z_NO_FLUSH);
      written = z.size() - s.avail_out;
    } while (s.avail_in > 0 || (mib == 1023 && s.avail_out == 0));
  }
  deflateEnd(&s);
  z.resize(written);
  return test::png_with_idat(16, 16, 0, z);
}

TEST(PictureBounds, ImageDataThatInflatesFarPastItsRowsIsRefusedNamingWhatTheyNeed) {
  const std::string png = inflate_bomb_png();
  ASSERT_LT(png.size(), 4 * kCapMiB);
  const test::ChildOutcome outcome = test::run_bounded(
      [&png] {
        const PngText text = read_png_text(png);  // what `vimg import` and every open read first
        return text.error + "\n" + errors_of(import_picture(png, "bomb.png", at_one_mm_per_pixel(16)));
      },
      256 * kCapMiB, 20);
  ASSERT_TRUE(outcome.finished()) << outcome.describe();
  const std::string what = "the image data inflates past the 272 bytes that the rows of its 16 x 16 pixels need (limit 272)";
  EXPECT_EQ(outcome.output, what + "\nbomb.png: error: cannot import the picture: " + what + "\n");
}

// A 5000 x 5000 maze (one-pixel walls and corridors): the corridors' outline turns at nearly every
// other pixel, tens of millions of points that no polygon may hold.
std::vector<std::uint8_t> maze_pixels(int side) {
  const std::vector<bool> corridor = test::maze_corridors(side, 5);
  std::vector<std::uint8_t> px(corridor.size());
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = corridor[i] ? 255 : 0;  // black walls
  return px;
}

TEST(PictureBounds, AMazeIsRefusedWhileItsOutlineIsTraced) {
  const int side = 4999;
  const std::string png = test::make_png(side, side, 1, maze_pixels(side));
  const test::ChildOutcome outcome = test::run_bounded(
      [&png] { return errors_of(import_picture(png, "maze.png", at_one_mm_per_pixel(side))); }, 512 * kCapMiB, 30);
  ASSERT_TRUE(outcome.finished()) << outcome.describe();
  EXPECT_EQ(outcome.output, "maze.png: error: an outline of gain 1 has more than " + std::to_string(kMaxPolygonPoints) +
                                " points (limit " + std::to_string(kMaxPolygonPoints) + "); use a smaller picture\n");
}

TEST(PictureBounds, AFineCheckerboardIsRefusedAtTheSurfaceLimitWhileTraced) {
  // 12.5 million black pixels touching only at their corners: as many outlines, each a surface.
  const int side = 5000;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 255);
  for (std::size_t y = 0; y < static_cast<std::size_t>(side); ++y) {
    for (std::size_t x = y % 2; x < static_cast<std::size_t>(side); x += 2) px[y * static_cast<std::size_t>(side) + x] = 0;
  }
  const std::string png = test::make_png(side, side, 1, px);
  px = {};
  const test::ChildOutcome outcome = test::run_bounded(
      [&png] { return errors_of(import_picture(png, "checker.png", at_one_mm_per_pixel(side))); }, 512 * kCapMiB, 30);
  ASSERT_TRUE(outcome.finished()) << outcome.describe();
  const std::string limit = std::to_string(kMaxImportPrimitives);
  EXPECT_EQ(outcome.output, "checker.png: error: the picture gives more than " + limit + " surfaces and groups (limit " +
                                limit + "); use fewer --levels or a smaller picture\n");
}

TEST(PictureBounds, HolesTestedAgainstManyLongOutlinesAreRefusedAtTheWorkLimit) {
  // docs/limits.md, kMaxPictureContainmentTests: 50 thin slanted lines whose boxes all hold a
  // black block with 7 400 one-pixel holes. The lines have the smaller areas, so each hole is tested
  // against every line (8 000 points each) before the block: 3e9 point tests, refused at 4e8.
  const int side = 2000;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 255);
  const auto paint = [&](int x, int y, std::uint8_t v) { px[static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x)] = v; };
  for (int line = 0; line < 50; ++line) {
    for (int x = 0; x < side; ++x) paint(x, 4 * line + x / 2, 0), paint(x, 4 * line + x / 2 + 1, 0);
  }
  for (int y = 210; y < 590; ++y) {
    for (int x = 1200; x < 1900; ++x) paint(x, y, 0);
  }
  for (int y = 213; y < 587; y += 6) {
    for (int x = 1203; x < 1897; x += 6) paint(x, y, 255);
  }
  const std::string png = test::make_png(side, side, 1, px);
  const test::ChildOutcome outcome = test::run_bounded(
      [&png] { return errors_of(import_picture(png, "holes.png", at_one_mm_per_pixel(side))); }, 512 * kCapMiB, 60);
  ASSERT_TRUE(outcome.finished()) << outcome.describe();
  EXPECT_EQ(outcome.output, "holes.png: error: the picture has too many holes in large outlines to import (limit 400000000 "
                            "point tests); use fewer --levels or a smaller picture\n");
}

// docs/limits.md: a picture import decodes at most kMaxPngPixels; one beyond says its size and the
// limit. The header alone decides: the image data is never inflated.
TEST(PictureBounds, APictureOverThePixelLimitIsRefusedWithItsSizeAndTheLimit) {
  const std::string png = test::png_with_idat(5000, 5001, 0, "not even zlib");
  const ImportResult r = import_picture(png, "big.png", at_one_mm_per_pixel(5000));
  EXPECT_EQ(errors_of(r), "big.png: error: cannot import the picture: the picture is 5000 x 5001 pixels, over the "
                          "limit of 25000000 pixels decoded (limit 25000000)\n");
}

TEST(PictureBounds, APictureOfExactlyThePixelLimitIsImported) {
  const int side = 5000;
  static_assert(5000.0 * 5000.0 == kMaxPngPixels);
  const std::string png = test::make_png(side, side, 1, std::vector<std::uint8_t>(25'000'000, 255));
  const test::ChildOutcome outcome = test::run_bounded(
      [&png] {
        const ImportResult r = import_picture(png, "white.png", at_one_mm_per_pixel(side));
        return r.ok() ? std::string("ok") : errors_of(r);
      },
      512 * kCapMiB, 30);
  EXPECT_EQ(outcome.output, "ok") << outcome.describe();
}

// docs/limits.md: PNG export writes at most kMaxPngPixels; a canvas one pixel row over is refused
// with its size and the limit, before anything is drawn.
TEST(PictureBounds, APngExportOverThePixelLimitIsRefusedWithItsSizeAndTheLimit) {
  Image image;
  image.width_mm = 5000.0;
  image.height_mm = 5000.0;
  PictureSize size;
  EXPECT_FALSE(picture_size(image, 1.0, size).has_value());
  EXPECT_EQ(size.width_px * size.height_px, 25'000'000);
  image.height_mm = 5000.5;
  const PngPieces png = encode_image_png(image, 1.0, 1);
  EXPECT_EQ(png.error, "a PNG of 5000 x 5001 pixels exceeds the limit of 25000000 pixels; use a smaller scale (limit 25000000)");
  EXPECT_TRUE(png.pieces.empty());
}

}  // namespace
}  // namespace vimg
