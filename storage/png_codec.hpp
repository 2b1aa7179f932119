#pragma once
// PNG images of a vibroimage (spec section 2): encoding a picture with the pHYs and `vibroimage`
// iTXt chunks, and reading the XML back out of a PNG. libpng errors never escape: every failure
// becomes a message.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/raster.hpp"

namespace vimg {

inline constexpr std::string_view kPngTextKeyword = "vibroimage";

// True when `bytes` start with the PNG signature.
bool looks_like_png(std::string_view bytes);

struct EncodedPng {
  std::string bytes;  // the PNG file
  std::string error;  // empty on success
};

// Encodes an RGB picture with a pHYs chunk of `pixels_per_metre` and an iTXt chunk `vibroimage`
// holding `xml` (compressed). On one thread; encode_png_pieces() does the work.
EncodedPng encode_png(const RgbRaster& raster, std::uint32_t pixels_per_metre, const std::string& xml);

// What a PNG shows and holds, made on demand, so that the encoder can draw, write and compress the
// parts on several threads at once (storage/png_encode.cpp).
// Threads: draw_band runs on several threads at once, for different bands; xml runs once, on one
// of them, while bands are drawn.
struct PngSource {
  int width_px = 0;
  int height_px = 0;
  std::uint32_t pixels_per_metre = 0;
  int band_rows = 64;  // rows per band; band b holds rows [b * band_rows, (b + 1) * band_rows)
  // Draws band `band`'s rows, 3 * width_px bytes of RGB each, the first at `first_row`, `stride`
  // bytes apart.
  std::function<void(int band, std::uint8_t* first_row, std::size_t stride)> draw_band;
  // The text of the `vibroimage` iTXt chunk; more than kMaxImageFileBytes is an error.
  std::function<std::string()> xml;
};

// A PNG file as pieces to be written one after the other (no copy into one block).
struct PngPieces {
  std::vector<std::string> pieces;
  std::string error;  // empty on success
  std::size_t size() const;
};

// Encodes `source` on `threads` threads (<= 0: one per core). The bytes are the same for any
// number of threads.
PngPieces encode_png_pieces(const PngSource& source, int threads);

struct PngText {
  std::optional<std::string> xml;  // the `vibroimage` text; empty when the PNG has none
  std::string error;               // what is wrong; empty if fine
  bool damaged = false;            // the error is damage (as opposed to a limit or a second chunk)
};

// Decodes the whole PNG (so damage anywhere is reported) and returns its one `vibroimage` text
// chunk (tEXt, zTXt or iTXt, compressed or not), read by us rather than by libpng so that a damaged
// chunk (bad CRC, bad zlib data), a text that inflates past kMaxImageFileBytes and a second
// vibroimage chunk are each reported as such.
PngText read_png_text(std::string_view bytes);

// The width in mm a PNG's pHYs chunk gives its pixels (unit: metre), when it comes before the
// pixels and gives a width in (0, kMaxCanvasMm]; nothing otherwise.
std::optional<double> png_physical_width_mm(std::string_view bytes);

struct DecodedPng {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, rows top to bottom
  std::string error;               // empty on success
};

// Decodes the pixels of any PNG (every colour type, bit depth and interlacing) as 8-bit RGBA, with
// the checks of read_png_text() and at most `max_pixels` pixels (picture import, docs/import.md).
DecodedPng decode_png_rgba(std::string_view bytes, double max_pixels);

}  // namespace vimg
