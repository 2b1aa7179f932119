// PNG images (spec section 2): a real picture at the chosen scale, pHYs at true size, the XML in an
// iTXt chunk `vibroimage`, exact restore, clear errors for foreign or damaged PNGs.
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/png_codec.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

struct Decoded {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
  const std::uint8_t* at(int x, int y) const { return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3; }
  int grey(int x, int y) const { return (at(x, y)[0] + at(x, y)[1] + at(x, y)[2]) / 3; }
};

Decoded decode(const std::string& bytes) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Decoded out;
  if (png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()) == 0) return out;
  image.format = PNG_FORMAT_RGB;
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr) == 0) return out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  return out;
}

// The (type, data) of every chunk, read straight from the bytes.
std::vector<std::pair<std::string, std::string>> chunks(const std::string& png) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t pos = 8;
  while (pos + 12 <= png.size()) {
    const auto b = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(png[i])); };
    const std::uint32_t length = b(pos) << 24 | b(pos + 1) << 16 | b(pos + 2) << 8 | b(pos + 3);
    out.emplace_back(png.substr(pos + 4, 4), png.substr(pos + 8, length));
    pos += 12 + length;
  }
  return out;
}

Image canvas(double w, double h) {
  Image image;
  image.width_mm = w;
  image.height_mm = h;
  return image;
}

Element with_id(std::string id, std::variant<Dot, Line, Surface, Group, UnknownElement> body) {
  Element e;
  e.id = std::move(id);
  e.body = std::move(body);
  return e;
}

std::string save_png(const Image& image, double scale, test::TempDir& dir, const std::string& name = "p.png") {
  const auto path = dir / name;
  SaveOptions options;
  options.scale_px_per_mm = scale;
  const auto error = save_image_file(image, path, options);
  EXPECT_FALSE(error.has_value()) << *error;
  return test::read_text_file(path);
}

TEST(Png, SizeAndPhysGiveTheTrueScale) {
  test::TempDir dir("png_size");
  const std::string png = save_png(canvas(70, 140), 10.0, dir);
  const Decoded d = decode(png);
  EXPECT_EQ(d.width, 700);
  EXPECT_EQ(d.height, 1400);
  bool found = false;
  for (const auto& [type, data] : chunks(png)) {
    if (type != "pHYs") continue;
    found = true;
    ASSERT_EQ(data.size(), 9u);
    const auto u = [&bytes = data](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])); };
    EXPECT_EQ(u(0) << 24 | u(1) << 16 | u(2) << 8 | u(3), 10000u) << "10 px/mm is 10000 px/m";
    EXPECT_EQ(u(4) << 24 | u(5) << 16 | u(6) << 8 | u(7), 10000u);
    EXPECT_EQ(u(8), 1u) << "unit: metre";
  }
  EXPECT_TRUE(found);
  const Decoded small = decode(save_png(canvas(10.05, 3), 2.5, dir, "s.png"));
  EXPECT_EQ(small.width, 26) << "ceil(10.05 * 2.5)";
  EXPECT_EQ(small.height, 8);
}

TEST(Png, ItxtChunkHoldsTheCanonicalXml) {
  test::TempDir dir("png_itxt");
  Image image = canvas(30, 20);
  image.children.push_back(with_id("d", Dot{10, 10, 2, 1}));
  const std::string png = save_png(image, 5.0, dir);
  int itxt = 0;
  for (const auto& [type, data] : chunks(png)) {
    if (type == "iTXt" && data.rfind("vibroimage", 0) == 0 && data[10] == '\0') ++itxt;
  }
  EXPECT_EQ(itxt, 1);
  const PngText text = read_png_text(png);
  ASSERT_TRUE(text.error.empty()) << text.error;
  ASSERT_TRUE(text.xml.has_value());
  EXPECT_EQ(*text.xml, write_image_xml(image));
}

TEST(Png, PictureShowsEachKindDistinctly) {
  test::TempDir dir("png_kinds");
  Image image = canvas(100, 60);
  Surface s;
  s.shape = SurfaceShape::rect;
  s.x_mm = 5;
  s.y_mm = 5;
  s.width_mm = 50;
  s.height_mm = 20;
  s.period_mm = 4.0;
  image.children.push_back(with_id("s", s));
  image.children.push_back(with_id("d", Dot{80, 15, 3.03, 1}));
  Line l;
  l.x1_mm = 10;
  l.y1_mm = 45;
  l.x2_mm = 90;
  l.y2_mm = 45;
  l.width_mm = 3;
  image.children.push_back(with_id("l", l));
  const double scale = 10.0;
  const Decoded d = decode(save_png(image, scale, dir));
  ASSERT_EQ(d.width, 1000);
  // Background stays white.
  EXPECT_EQ(d.grey(2, 2), 255);
  EXPECT_EQ(d.grey(995, 595), 255);
  // A dot is a dark disc: dark at the centre, white beyond its radius.
  EXPECT_LT(d.grey(800, 150), 60);
  EXPECT_EQ(d.grey(800 + 40, 150), 255);
  // Its edge is anti-aliased: some pixel on the rim is between dark and white.
  bool intermediate = false;
  for (int x = 800 + 25; x <= 800 + 35; ++x) intermediate |= d.grey(x, 150) > 60 && d.grey(x, 150) < 250;
  EXPECT_TRUE(intermediate);
  // A line is coloured (not grey) inside its band only.
  const auto* line_px = d.at(500, 450);
  EXPECT_GT(std::abs(line_px[0] - line_px[2]), 40);
  EXPECT_EQ(d.grey(500, 450 + 25), 255);
  // The surface's stripes repeat at its period: the grey level along a row has period 40 px.
  std::vector<double> row;
  for (int x = 60; x < 540; ++x) row.push_back(d.grey(x, 150));
  double best_corr = -1e9;
  int best_lag = 0;
  for (int lag = 10; lag < 80; ++lag) {
    double c = 0;
    for (std::size_t i = 0; i + lag < row.size(); ++i) c += (row[i] - 128) * (row[i + lag] - 128);
    c /= static_cast<double>(row.size() - lag);
    if (c > best_corr) {
      best_corr = c;
      best_lag = lag;
    }
  }
  EXPECT_NEAR(best_lag, 4.0 * scale, 1.0);
  // The surface colour differs from the dot's and the line's.
  const auto* surface_px = d.at(300, 150);
  EXPECT_GT(surface_px[2], surface_px[0]);
  EXPECT_GT(line_px[0], line_px[2]) << "a 175 Hz line is warm-coloured";
}

TEST(Png, SquarePatternHasTwoLevelsSineHasMany) {
  test::TempDir dir("png_patterns");
  for (const SurfacePattern pattern : {SurfacePattern::square, SurfacePattern::sine}) {
    Image image = canvas(40, 10);
    Surface s;
    s.shape = SurfaceShape::rect;
    s.x_mm = 0;
    s.y_mm = 0;
    s.width_mm = 40;
    s.height_mm = 10;
    s.period_mm = 5;
    s.pattern = pattern;
    image.children.push_back(with_id("s", s));
    const Decoded d = decode(save_png(image, 10.0, dir));
    std::vector<int> levels;
    for (int x = 0; x < 400; ++x) levels.push_back(d.grey(x, 50));
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    if (pattern == SurfacePattern::square) {
      EXPECT_LE(levels.size(), 2u);
    } else {
      EXPECT_GT(levels.size(), 10u);
    }
  }
}

TEST(Png, LoadingRestoresTheImageExactly) {
  test::TempDir dir("png_restore");
  const LoadResult xml = load_image_file(std::string(VIMG_TEST_DATA_DIR) + "/valid/unknown_extensions.vimg");
  ASSERT_TRUE(xml.ok());
  save_png(*xml.image, 3.0, dir);
  const LoadResult png = load_image_file(dir / "p.png");
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(*png.image, *xml.image);
}

TEST(Png, PlainPngIsAClearError) {
  test::TempDir dir("png_plain");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = 4;
  image.height = 4;
  image.format = PNG_FORMAT_GRAY;
  std::vector<std::uint8_t> pixels(16, 128);
  const auto path = dir / "photo.png";
  ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, pixels.data(), 0, nullptr), 0);
  const LoadResult r = load_image_file(path);
  ASSERT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_NE(r.diagnostics[0].to_string().find("photo.png: error: this PNG has no 'vibroimage' text chunk"),
            std::string::npos);
}

TEST(Png, DamagedBytesNeverCrashAndNeverHalfLoad) {
  test::TempDir dir("png_damage");
  const LoadResult smiley = load_image_file(std::string(VIMG_SOURCE_DIR) + "/assets/examples/smiley.vimg");
  ASSERT_TRUE(smiley.ok());
  const std::string good = save_png(*smiley.image, 1.0, dir);
  std::mt19937 rng(3);
  int errors = 0;
  for (int round = 0; round < 300; ++round) {
    std::string bad = good;
    if (round % 3 == 0) {
      bad.resize(std::uniform_int_distribution<std::size_t>(0, good.size() - 1)(rng));
    } else {
      for (int k = std::uniform_int_distribution<int>(1, 8)(rng); k > 0; --k) {
        bad[std::uniform_int_distribution<std::size_t>(0, bad.size() - 1)(rng)] =
            static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
      }
    }
    test::write_text_file(dir / "bad.png", bad);
    const LoadResult r = load_image_file(dir / "bad.png");
    if (r.ok()) {
      EXPECT_EQ(*r.image, *smiley.image) << "a damaged PNG either loads exactly or fails";
    } else {
      ++errors;
      EXPECT_TRUE(has_errors(r.diagnostics));
    }
  }
  EXPECT_GT(errors, 100);
}

TEST(Png, TruncatedPngNamesTheDamage) {
  test::TempDir dir("png_trunc");
  const std::string good = save_png(canvas(20, 20), 4.0, dir);
  test::write_text_file(dir / "cut.png", good.substr(0, good.size() / 2));
  const LoadResult r = load_image_file(dir / "cut.png");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics[0].message.find("damaged PNG"), std::string::npos) << r.diagnostics[0].message;
}

TEST(Png, ChunkClaimingMoreBytesThanTheFileIsRejectedBeforeAllocating) {
  test::TempDir dir("png_lie");
  std::string png = save_png(canvas(20, 20), 1.0, dir);
  // Make the first chunk after IHDR claim about 2 GB.
  const std::size_t second_chunk = 8 + 12 + 13;
  png[second_chunk] = '\x7f';
  const PngText text = read_png_text(png);
  EXPECT_EQ(text.error, "the file ends too early (a chunk claims 2130706441 bytes)");
  EXPECT_FALSE(text.xml.has_value());
}

TEST(Png, BadScaleOrHugePictureIsAnErrorAndWritesNothing) {
  test::TempDir dir("png_limits");
  for (const double scale : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    const auto error = save_image_file(canvas(10, 10), dir / "x.png", {scale});
    ASSERT_TRUE(error.has_value());
    EXPECT_NE(error->find("scale"), std::string::npos);
  }
  const auto error = save_image_file(canvas(10000, 10000), dir / "x.png", {10.0});
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->find("exceeds the limit"), std::string::npos) << *error;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "no temporary file is left behind";
}

}  // namespace
}  // namespace vimg
