// The PNG encoder draws and compresses bands, and writes and compresses the XML text in parts, on
// several threads (storage/png_encode.cpp). Whatever the number of threads, the file is the same
// bytes, libpng decodes exactly the drawn picture, and the text chunk holds exactly the XML.
// Runs under TSan (label threaded).
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/picture.hpp"
#include "storage/png_codec.hpp"
#include "../storage/storage_test_support.hpp"

namespace vimg {
namespace {

std::string joined(const PngPieces& png) {
  std::string bytes;
  for (const std::string& piece : png.pieces) bytes += piece;
  return bytes;
}

PngPieces encode_image(const Image& image, double scale, int threads) {
  return encode_image_png(image, scale, threads);
}

// The picture libpng decodes equals draw_picture's, pixel for pixel.
void expect_same_picture(const std::string& png, const Image& image, double scale) {
  RgbRaster drawn;
  ASSERT_FALSE(draw_picture(image, scale, drawn).has_value());
  const DecodedPng decoded = decode_png_rgba(png, kMaxDecodedPngPixels);
  ASSERT_TRUE(decoded.error.empty()) << decoded.error;
  ASSERT_EQ(decoded.width, drawn.width);
  ASSERT_EQ(decoded.height, drawn.height);
  std::size_t differing = 0;
  for (std::size_t p = 0; p < static_cast<std::size_t>(drawn.width) * drawn.height; ++p) {
    for (int c = 0; c < 3; ++c) differing += decoded.rgba[p * 4 + c] != drawn.rgb[p * 3 + c];
    differing += decoded.rgba[p * 4 + 3] != 255;
  }
  EXPECT_EQ(differing, 0u);
}

TEST(PngParallel, SameBytesOnAnyNumberOfThreadsAndExactPictureAndText) {
  test::RandomImages random(2026);
  for (int trial = 0; trial < 6; ++trial) {
    Image image = random.make(400);
    // Heights that are and are not multiples of a band; one row; one band.
    const double heights_mm[] = {64.0, 37.3, 0.1, 6.4, 130.05, 200.0};
    image.height_mm = heights_mm[trial];
    image.width_mm = trial == 2 ? 0.1 : 80.0 + 10.0 * trial;
    const double scale = 10.0;
    const PngPieces one = encode_image(image, scale, 1);
    ASSERT_TRUE(one.error.empty()) << one.error;
    const std::string bytes = joined(one);
    EXPECT_EQ(one.size(), bytes.size());
    for (const int threads : {2, 3, 7}) {
      const PngPieces many = encode_image(image, scale, threads);
      ASSERT_TRUE(many.error.empty()) << many.error;
      EXPECT_TRUE(joined(many) == bytes) << "trial " << trial << ": " << threads << " threads";
    }
    expect_same_picture(bytes, image, scale);
    const PngText text = read_png_text(bytes);
    ASSERT_TRUE(text.error.empty()) << text.error;
    ASSERT_TRUE(text.xml.has_value());
    EXPECT_TRUE(*text.xml == write_image_xml(image)) << "trial " << trial;
  }
}

TEST(PngParallel, TextOfManyPartsReadsBackWhole) {
  // 5 MiB of text: five parts of 1 MiB compressed at once, each cut mid-element.
  std::string xml;
  std::mt19937 rng(5);
  while (xml.size() < 5 * kMiB + 12345) {
    xml += "<dot id=\"d" + std::to_string(rng()) + "\" x=\"" + std::to_string(rng() % 1000) + ".5\"/>\n";
  }
  PngSource source;
  source.width_px = 3;
  source.height_px = 130;
  source.pixels_per_metre = 10000;
  source.draw_band = [](int band, std::uint8_t* row, std::size_t stride) {
    for (int r = 0; r < 64; ++r) {
      if (band * 64 + r >= 130) break;
      for (int i = 0; i < 9; ++i) row[static_cast<std::size_t>(r) * stride + i] = static_cast<std::uint8_t>(band * 64 + r + i);
    }
  };
  source.xml = [&] { return xml; };
  const std::string bytes = joined(encode_png_pieces(source, 3));
  const PngText text = read_png_text(bytes);
  ASSERT_TRUE(text.error.empty()) << text.error;
  ASSERT_TRUE(text.xml.has_value());
  EXPECT_TRUE(*text.xml == xml);
  const DecodedPng decoded = decode_png_rgba(bytes, 1e6);
  ASSERT_TRUE(decoded.error.empty()) << decoded.error;
  for (int y = 0; y < 130; ++y) {
    for (int x = 0; x < 3; ++x) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(decoded.rgba[(static_cast<std::size_t>(y) * 3 + x) * 4 + c], static_cast<std::uint8_t>(y + 3 * x + c))
            << x << "," << y;
      }
    }
  }
}

TEST(PngParallel, AFailingBandOrAnOversizedTextIsAnErrorWithNoBytes) {
  PngSource source;
  source.width_px = 10;
  source.height_px = 640;
  source.pixels_per_metre = 10000;
  source.draw_band = [](int band, std::uint8_t*, std::size_t) {
    if (band == 4) throw std::runtime_error("band 4 cannot be drawn");
  };
  source.xml = [] { return std::string("<x/>"); };
  const PngPieces failed = encode_png_pieces(source, 3);
  EXPECT_NE(failed.error.find("band 4 cannot be drawn"), std::string::npos) << failed.error;
  EXPECT_TRUE(failed.pieces.empty());

  source.draw_band = [](int, std::uint8_t*, std::size_t) {};
  source.xml = [] { return std::string(kMaxImageFileBytes + 1, 'x'); };
  const PngPieces too_long = encode_png_pieces(source, 2);
  EXPECT_NE(too_long.error.find("(limit " + std::to_string(kMaxImageFileBytes) + ")"), std::string::npos)
      << too_long.error;
  EXPECT_TRUE(too_long.pieces.empty());
}

TEST(PngParallel, SavedFileIsTheEncodedBytesAndLoadsBack) {
  test::TempDir dir("png_parallel");
  test::RandomImages random(99);
  const Image image = random.make(200);
  SaveOptions options;
  options.scale_px_per_mm = 4.0;
  options.threads = 3;
  const auto path = dir / "saved.png";
  ASSERT_FALSE(save_image_file(image, path, options).has_value());
  EXPECT_TRUE(test::read_text_file(path) == joined(encode_image(image, 4.0, 1)));
  const LoadResult loaded = load_image_file(path);
  ASSERT_TRUE(loaded.ok());
  EXPECT_TRUE(*loaded.image == image);
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) files += entry.is_regular_file();
  EXPECT_EQ(files, 1u) << "no temporary is left";
}

}  // namespace
}  // namespace vimg
