// What the raw bytes of a PNG say before libpng decodes them: the picture's size (zero, which PNG
// forbids, or over the limits), and how far its image data inflates (docs/limits.md, "PNG").
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "storage/limits.hpp"
#include "storage/png_codec_detail.hpp"

namespace vimg::png_detail {

namespace {

struct Header {
  std::uint64_t width = 0;
  std::uint64_t height = 0;
  int bits_per_pixel = 0;
  bool interlaced = false;
};

// IHDR when it is the first chunk and its colour type and bit depth go together.
std::optional<Header> header_of(std::string_view bytes) {
  if (bytes.size() < 33 || bytes.compare(12, 4, "IHDR") != 0 || be32(bytes, 8) != 13) return std::nullopt;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  const int depth = byte(24), colour = byte(25), interlace = byte(28);
  int channels = 0;
  switch (colour) {
    case 0: channels = 1; break;                                     // grey: 1, 2, 4, 8, 16 bits
    case 2: channels = depth >= 8 ? 3 : 0; break;                    // RGB: 8, 16
    case 3: channels = depth <= 8 ? 1 : 0; break;                    // palette: 1, 2, 4, 8
    case 4: channels = depth >= 8 ? 2 : 0; break;                    // grey and alpha: 8, 16
    case 6: channels = depth >= 8 ? 4 : 0; break;                    // RGBA: 8, 16
    default: break;
  }
  const bool depth_ok = depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16;
  if (channels == 0 || !depth_ok || interlace > 1) return std::nullopt;
  return Header{be32(bytes, 16), be32(bytes, 20), depth * channels, interlace == 1};
}

// Bytes of the filtered rows of a width x height (sub)image: a filter byte and the pixels per row.
std::uint64_t rows_bytes(std::uint64_t width, std::uint64_t height, int bits_per_pixel) {
  if (width == 0 || height == 0) return 0;
  return height * (1 + (width * static_cast<std::uint64_t>(bits_per_pixel) + 7) / 8);
}

// What the image data inflates to: the rows of the picture, or of its seven Adam7 passes.
std::uint64_t expected_bytes(const Header& h) {
  if (!h.interlaced) return rows_bytes(h.width, h.height, h.bits_per_pixel);
  struct Pass {
    std::uint64_t x0, y0, dx, dy;
  };
  constexpr std::array<Pass, 7> kAdam7 = {{{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4},
                                           {1, 0, 2, 2}, {0, 1, 1, 2}}};
  std::uint64_t total = 0;
  for (const Pass& p : kAdam7) {
    const std::uint64_t w = h.width > p.x0 ? (h.width - p.x0 + p.dx - 1) / p.dx : 0;
    const std::uint64_t rows = h.height > p.y0 ? (h.height - p.y0 + p.dy - 1) / p.dy : 0;
    total += rows_bytes(w, rows, h.bits_per_pixel);
  }
  return total;
}

class RawInflater {
 public:
  RawInflater() { ok_ = inflateInit2(&z_, -15) == Z_OK; }
  ~RawInflater() {
    if (ok_) inflateEnd(&z_);
  }
  RawInflater(const RawInflater&) = delete;
  RawInflater& operator=(const RawInflater&) = delete;
  bool ok() const { return ok_; }
  z_stream& stream() { return z_; }

 private:
  z_stream z_{};
  bool ok_ = false;
};

}  // namespace

std::optional<std::string> size_problem(std::string_view bytes, double max_pixels) {
  if (bytes.size() < 24 || bytes.compare(12, 4, "IHDR") != 0) return std::nullopt;  // libpng reports it
  const std::uint32_t width = be32(bytes, 16), height = be32(bytes, 20);
  // PNG specification, 11.2.2 IHDR: "Zero is an invalid value" for the width and the height.
  if (width == 0 || height == 0) {
    const std::string gives = width == 0 && height == 0 ? "a width and a height of 0" : width == 0 ? "a width of 0" : "a height of 0";
    return "the PNG header gives " + gives + "; PNG requires a width and height of at least 1";
  }
  const std::string size = "the picture is " + std::to_string(width) + " x " + std::to_string(height) + " pixels";
  if (width > static_cast<std::uint32_t>(kMaxPngSide) || height > static_cast<std::uint32_t>(kMaxPngSide)) {
    return size + ", over the limit of " + std::to_string(kMaxPngSide) + " pixels a side (limit " +
           std::to_string(kMaxPngSide) + ")";
  }
  if (static_cast<double>(width) * static_cast<double>(height) > max_pixels) {
    const auto limit = std::to_string(static_cast<std::uint64_t>(max_pixels));
    return size + ", over the limit of " + limit + " pixels decoded (limit " + limit + ")";
  }
  return std::nullopt;
}

std::optional<std::string> image_data_over_rows(std::string_view bytes) {
  const std::optional<Header> header = header_of(bytes);
  if (!header) return std::nullopt;
  const std::uint64_t expected = expected_bytes(*header);
  RawInflater inflater;
  if (!inflater.ok()) return std::nullopt;  // libpng will say it has no memory
  z_stream& z = inflater.stream();
  std::array<unsigned char, 65536> scratch;
  std::uint64_t produced = 0;
  std::size_t header_left = 2;  // the zlib header; the deflate data follows it
  bool done = false;
  for_each_chunk(bytes, [&](const RawChunk& c) {
    if (c.type != "IDAT") return true;
    std::string_view data = c.data;
    const std::size_t skip = std::min(header_left, data.size());
    header_left -= skip;
    data.remove_prefix(skip);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));  // zlib never writes its input
    z.avail_in = static_cast<uInt>(data.size());
    while (z.avail_in > 0 && !done) {
      // Never more than one byte past the rows.
      const std::uint64_t room = std::min<std::uint64_t>(scratch.size(), expected + 1 - produced);
      z.next_out = scratch.data();
      z.avail_out = static_cast<uInt>(room);
      const int status = inflate(&z, Z_NO_FLUSH);
      produced += room - z.avail_out;
      if (produced > expected || status != Z_OK) done = true;  // too much, the end, or damage
    }
    return !done;
  });
  if (produced <= expected) return std::nullopt;
  const std::string limit = std::to_string(expected);
  return "the image data inflates past the " + limit + " bytes that the rows of its " + std::to_string(header->width) +
         " x " + std::to_string(header->height) + " pixels need (limit " + limit + ")";
}

}  // namespace vimg::png_detail
