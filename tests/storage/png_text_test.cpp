// The `vibroimage` text chunk of a PNG (docs/format-png.md "PNG"): tEXt, zTXt and iTXt (compressed or
// not) are read; a damaged chunk, a text that inflates past the XML size limit and a second
// vibroimage chunk are each reported for what they are, never as "no vibroimage chunk".
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/png_codec.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

const std::string kXml =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<vibroimage version=\"1.0\" width=\"10\" height=\"10\">\n"
    "  <dot id=\"d\" x=\"5\" y=\"5\" radius=\"1\" gain=\"1\"/>\n</vibroimage>\n";

std::string be32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8), static_cast<char>(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  const std::string body = type + data;
  const auto crc = static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
  return be32(static_cast<std::uint32_t>(data.size())) + body + be32(crc);
}

std::string deflated(const std::string& text) {
  uLongf size = compressBound(static_cast<uLong>(text.size()));
  std::string out(size, '\0');
  EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(text.data()),
                      static_cast<uLong>(text.size()), 9),
            Z_OK);
  out.resize(size);
  return out;
}

std::string itxt(const std::string& text, bool compressed, const std::string& keyword = "vibroimage") {
  return chunk("iTXt", keyword + std::string("\0", 1) + (compressed ? std::string("\1\0", 2) : std::string("\0\0", 2)) +
                           std::string("\0\0", 2) + (compressed ? deflated(text) : text));
}

// A valid 4 x 4 PNG (no text) split at the end of IHDR, so that text chunks can go in between.
struct PngParts {
  std::string head;  // signature and IHDR
  std::string tail;  // IDAT and IEND
};

PngParts plain_png() {
  RgbRaster raster;
  raster.width = 4;
  raster.height = 4;
  raster.rgb.assign(48, 200);
  const EncodedPng png = encode_png(raster, 1000, "");
  EXPECT_TRUE(png.error.empty());
  PngParts parts;
  std::size_t pos = 8;
  std::string middle;
  while (pos + 12 <= png.bytes.size()) {
    const auto b = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(png.bytes[i])); };
    const std::uint32_t length = b(pos) << 24 | b(pos + 1) << 16 | b(pos + 2) << 8 | b(pos + 3);
    const std::string type = png.bytes.substr(pos + 4, 4);
    const std::string whole = png.bytes.substr(pos, 12 + length);
    if (type == "IHDR") parts.head = png.bytes.substr(0, 8) + whole;
    else if (type == "IDAT" || type == "IEND") parts.tail += whole;
    pos += 12 + length;
  }
  return parts;
}

LoadResult load(const std::string& png, test::TempDir& dir) {
  test::write_text_file(dir / "t.png", png);
  return load_image_file(dir / "t.png");
}

std::string only_message(const LoadResult& r) {
  EXPECT_EQ(r.diagnostics.size(), 1u);
  return r.diagnostics.empty() ? "" : r.diagnostics[0].to_string();
}

TEST(PngText, EveryTextChunkKindIsRead) {
  test::TempDir dir("png_kinds");
  const PngParts p = plain_png();
  const std::string z = chunk("zTXt", "vibroimage" + std::string("\0\0", 2) + deflated(kXml));
  const std::string t = chunk("tEXt", "vibroimage" + std::string("\0", 1) + kXml);
  for (const std::string& text : {itxt(kXml, true), itxt(kXml, false), z, t}) {
    const LoadResult r = load(p.head + chunk("tEXt", std::string("Comment\0hello", 13)) + text + p.tail, dir);
    ASSERT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].to_string());
    EXPECT_EQ(write_image_xml(*r.image), kXml);
  }
}

TEST(PngText, DamagedCompressedTextIsReportedAsDamaged) {
  test::TempDir dir("png_zlib");
  const PngParts p = plain_png();
  std::string data = deflated(kXml);
  data[data.size() / 2] = static_cast<char>(data[data.size() / 2] ^ 0x5A);
  data.resize(data.size() - 3);
  const std::string bad = chunk("iTXt", "vibroimage" + std::string("\0\1\0\0\0", 5) + data);
  const std::string message = only_message(load(p.head + bad + p.tail, dir));
  EXPECT_EQ(message.rfind((dir / "t.png").string() + ": error: damaged PNG: the 'vibroimage' iTXt chunk is damaged (", 0), 0u)
      << message;
}

TEST(PngText, TextChunkWithAWrongCrcIsReportedAsDamaged) {
  test::TempDir dir("png_crc");
  const PngParts p = plain_png();
  std::string text = itxt(kXml, true);
  text[text.size() - 1] = static_cast<char>(text[text.size() - 1] ^ 1);
  EXPECT_EQ(only_message(load(p.head + text + p.tail, dir)),
            (dir / "t.png").string() + ": error: damaged PNG: the 'vibroimage' iTXt chunk is damaged (CRC mismatch)");
}

TEST(PngText, TextOverTheSizeLimitIsRefusedWithTheLimit) {
  test::TempDir dir("png_big");
  const PngParts p = plain_png();
  std::string huge = kXml;
  huge.append(kMaxImageFileBytes + 2 * kMiB, ' ');  // 66 MiB of text in about 66 KB of deflate
  const std::string png = p.head + itxt(huge, true) + p.tail;
  ASSERT_LT(png.size(), 1'000'000u);
  EXPECT_EQ(only_message(load(png, dir)),
            (dir / "t.png").string() +
                ": error: the 'vibroimage' text of this PNG inflates to more than 67108864 bytes (limit 67108864)");
}

TEST(PngText, TwoVibroimageChunksAreRefused) {
  test::TempDir dir("png_two");
  const PngParts p = plain_png();
  const std::string other = "<vibroimage version=\"1.0\" width=\"99\" height=\"99\"/>";
  EXPECT_EQ(only_message(load(p.head + itxt(kXml, true) + itxt(other, false) + p.tail, dir)),
            (dir / "t.png").string() +
                ": error: this PNG holds 2 'vibroimage' text chunks; a vibroimage has exactly one");
}

TEST(PngText, APngWithoutTheChunkIsStillNotAVibroimage) {
  test::TempDir dir("png_none");
  const PngParts p = plain_png();
  const std::string message = only_message(load(p.head + itxt(kXml, false, "Comment") + p.tail, dir));
  EXPECT_NE(message.find("this PNG has no 'vibroimage' text chunk"), std::string::npos) << message;
}

}  // namespace
}  // namespace vimg
