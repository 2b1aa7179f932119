#pragma once
// Internal to storage/png_*.cpp: the libpng error sink and callbacks, the libpng read pass shared by
// picture decoding and text reading, and the chunk walking of the raw bytes. Not part of the API.
#include <png.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "storage/limits.hpp"

namespace vimg::png_detail {

struct ErrorSink {
  char message[256] = {};
};

extern "C" void on_png_error(png_structp png, png_const_charp message);
extern "C" void on_png_warning(png_structp, png_const_charp);

struct ReadSource {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t offset = 0;
};

struct ReadState {
  ReadSource source;
  unsigned char* row = nullptr;  // malloc'ed; freed by the caller on every path
  // decode_png_rgba only: the whole picture as 8-bit RGBA rows, into the caller's `pixels` of
  // `pixel_bytes` (a picture that needs more is an error).
  bool keep_pixels = false;
  double max_pixels = kMaxDecodedPngPixels;
  unsigned char* pixels = nullptr;
  std::size_t pixel_bytes = 0;
  png_uint_32 width = 0;
  png_uint_32 height = 0;
};

// Returns true when the whole PNG decodes; no C++ objects live here.
bool decode_text(ReadState* state, ErrorSink* sink);

// libpng allocates a chunk's declared length before reading it; a chunk can never be longer than
// the bytes that follow it, so such lies are caught here, before any allocation.
bool chunk_lengths_fit(std::string_view bytes, ErrorSink* sink);

// The picture's size from IHDR (the first chunk): a width or height of 0, which PNG forbids ("the
// PNG header gives a width of 0; PNG requires a width and height of at least 1"), or a size over
// kMaxPngSide or `max_pixels` (a limit, not damage, named with the size). libpng would only say
// "Invalid IHDR data" for either. Nothing when the size is fine or when there is no IHDR first
// (libpng reports that). storage/png_image_data.cpp.
std::optional<std::string> size_problem(std::string_view bytes, double max_pixels);

// The image data (IDAT) inflated no further than one byte past what the rows IHDR declares need,
// so that data that inflates far beyond them (a small picture whose data inflates to gigabytes)
// costs no more than the picture. Returns the refusal, naming the bytes expected; nothing when the
// data fits, or when IHDR or the data is damaged (libpng reports that). storage/png_image_data.cpp.
std::optional<std::string> image_data_over_rows(std::string_view bytes);

// The big-endian 32-bit number at `pos` of `bytes`.
std::uint32_t be32(std::string_view bytes, std::size_t pos);

// One chunk of the raw bytes: its type, its data, and where its CRC sits.
struct RawChunk {
  std::string_view type;
  std::string_view data;
  std::size_t pos = 0;  // of its length field
};

// Calls visit(chunk) for each chunk after the signature, in order, until IEND, a chunk cut short,
// or visit returning false.
template <class Visit>
void for_each_chunk(std::string_view bytes, Visit&& visit) {
  std::size_t pos = 8;
  while (pos + 12 <= bytes.size()) {
    const std::uint32_t length = be32(bytes, pos);
    if (length > bytes.size() - pos - 12) return;
    const std::string_view type = bytes.substr(pos + 4, 4);
    if (type == "IEND") return;
    if (!visit(RawChunk{type, bytes.substr(pos + 8, length), pos})) return;
    pos += 12 + static_cast<std::size_t>(length);
  }
}

}  // namespace vimg::png_detail
