// A PNG whose signature a transfer damaged (PngSuite's xcrn0g04, xlfn0g04, xs1n0g01, xs2n0g01,
// xs4n0g01 and xs7n0g01, made here from a valid vibroimage PNG) is refused as "a damaged PNG
// signature" with the likely cause, not as text or UTF-16; an intact signature with damage after it
// (xhdn0g08: a bad IHDR checksum) is still the PNG reader's "damaged PNG".
#include <gtest/gtest.h>

#include <string>

#include "storage/foreign_file.hpp"
#include "storage/image_io.hpp"
#include "storage/import/import.hpp"
#include "storage/png_codec.hpp"
#include "storage/png_signature.hpp"
#include "storage_test_support.hpp"

namespace vimg {
namespace {

const std::string kTail = "; copy the file again as binary data";

std::string valid_png() {
  RgbRaster raster;
  raster.width = 4;
  raster.height = 3;
  raster.rgb.assign(4 * 3 * 3, 200);
  const EncodedPng png = encode_png(
      raster, 1000, "<vibroimage version=\"1.0\" width=\"10\" height=\"10\"><dot x=\"1\" y=\"1\" radius=\"1\"/></vibroimage>");
  EXPECT_EQ(png.error, "");
  return png.bytes;
}

// What `vimg validate` and the editor say of `bytes` as a file: the first error's message.
std::string load_message(const std::string& bytes) {
  const test::TempDir dir("png_signature");
  test::write_text_file(dir / "damaged.png", bytes);
  const LoadResult r = load_image_file(dir / "damaged.png");
  if (r.diagnostics.empty()) return "";
  EXPECT_FALSE(r.ok());
  return r.diagnostics.front().message;
}

// Every LF of the file as CR LF (unix2dos on every LF, or only on LFs without a CR before them).
std::string lf_to_crlf(const std::string& bytes, bool lone_lf_only) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i] == '\n' && !(lone_lf_only && i > 0 && bytes[i - 1] == '\r')) out += '\r';
    out += bytes[i];
  }
  return out;
}

// Every CR LF of the file as LF (dos2unix).
std::string crlf_to_lf(const std::string& bytes) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (bytes[i] == '\r' && i + 1 < bytes.size() && bytes[i + 1] == '\n') continue;
    out += bytes[i];
  }
  return out;
}

std::string with_byte(std::string bytes, std::size_t at, char value) {
  bytes[at] = value;
  return bytes;
}

TEST(PngSignature, TheValidPngLoadsAndIsNotDamaged) {
  const std::string png = valid_png();
  EXPECT_FALSE(damaged_png_signature(png));
  EXPECT_FALSE(foreign_file_kind(png));
  EXPECT_EQ(load_message(png), "");
}

TEST(PngSignature, CrLfBecameLfByATextModeTransfer) {  // xlfn0g04's kind of damage, from DOS to Unix
  const std::string expected = "a damaged PNG signature: line endings changed by a text-mode transfer (the signature's "
                               "CR LF became LF)" + kTail;
  EXPECT_EQ(load_message(crlf_to_lf(valid_png())), expected);
}

TEST(PngSignature, LfBecameCrLfByATextModeTransfer) {  // xcrn0g04's kind of damage, from Unix to DOS
  EXPECT_EQ(load_message(lf_to_crlf(valid_png(), false)),
            "a damaged PNG signature: line endings changed by a text-mode transfer (the signature's CR LF became "
            "CR CR LF and its LF became CR LF)" + kTail);
  EXPECT_EQ(load_message(lf_to_crlf(valid_png(), true)),
            "a damaged PNG signature: line endings changed by a text-mode transfer (the signature's LF became CR LF)" + kTail);
}

TEST(PngSignature, TheFirstByteLostItsHighBit) {  // xs1n0g01: was "text that is not XML, starting with 'PNG'"
  const std::string damaged = with_byte(valid_png(), 0, '\x09');
  EXPECT_EQ(load_message(damaged), "a damaged PNG signature: the first byte lost its high bit (0x09 where a PNG has "
                                   "0x89), as a 7-bit transfer does" + kTail);
  EXPECT_EQ(load_message(crlf_to_lf(damaged)),
            "a damaged PNG signature: line endings changed by a text-mode transfer (the signature's CR LF became LF); "
            "its first byte lost its high bit too" + kTail);
}

TEST(PngSignature, OneByteChangedIsNamedWithWhatAPngHas) {  // xs2n0g01, xs4n0g01, xs7n0g01
  EXPECT_EQ(load_message(with_byte(valid_png(), 1, 'Q')),
            "a damaged PNG signature: one byte changed (byte 2 is 0x51 'Q' where a PNG has 0x50 'P')" + kTail);
  EXPECT_EQ(load_message(with_byte(valid_png(), 3, 'g')),
            "a damaged PNG signature: one byte changed (byte 4 is 0x67 'g' where a PNG has 0x47 'G')" + kTail);
  EXPECT_EQ(load_message(with_byte(valid_png(), 6, ' ')),
            "a damaged PNG signature: one byte changed (byte 7 is 0x20 where a PNG has 0x1A)" + kTail);
}

TEST(PngSignature, ImportingAPictureSaysTheSame) {  // vimg import, the editor's File -> Import
  const test::TempDir dir("png_signature_import");
  test::write_text_file(dir / "picture.png", crlf_to_lf(valid_png()));
  const ImportResult r = import_file(dir / "picture.png", ImportOptions{});
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_FALSE(r.image);
  EXPECT_EQ(r.diagnostics.front().message, "a damaged PNG signature: line endings changed by a text-mode transfer (the "
                                           "signature's CR LF became LF)" + kTail);
}

TEST(PngSignature, AFileThatEndsWithinTheSignature) {
  EXPECT_EQ(load_message(valid_png().substr(0, 5)),
            "a damaged PNG signature: the file ends within the signature (5 of its 8 bytes)" + kTail);
}

TEST(PngSignature, DamageAfterAnIntactSignatureIsThePngReaders) {  // xhdn0g08: a bad IHDR checksum
  const std::string png = valid_png();
  const std::string damaged = with_byte(png, 29, static_cast<char>(png[29] ^ 0x01));  // IHDR's CRC: bytes 29-32
  EXPECT_FALSE(damaged_png_signature(damaged));
  EXPECT_EQ(load_message(damaged).rfind("damaged PNG: ", 0), 0u) << load_message(damaged);
}

TEST(PngSignature, TextAndOtherFilesAreNotDamagedPngs) {
  EXPECT_FALSE(damaged_png_signature("PNG is a picture format\n"));
  EXPECT_FALSE(damaged_png_signature("\x89PN"));
  EXPECT_FALSE(damaged_png_signature(std::string("\x8AMNG\r\n\x1A\n", 8)));  // another format of the family
  EXPECT_FALSE(damaged_png_signature(std::string("\x89PNG\r\n\x1A\n", 8)));
  const auto text = foreign_file_kind("PNG is a picture format\n");
  ASSERT_TRUE(text);
  EXPECT_FALSE(text->damaged_png);
  EXPECT_EQ(text->what, "text that is not XML, starting with 'PNG is a picture format'");
  EXPECT_EQ(foreign_file_kind(std::string("\x8AMNG\r\n\x1A\n", 8))->what, "an MNG animation");
}

}  // namespace
}  // namespace vimg
