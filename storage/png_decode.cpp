// PNG decoding with libpng: the read pass over the whole file (every chunk checked, text chunks
// skipped) and the picture as 8-bit RGBA. libpng reports errors by longjmp: decode_text() holds no
// C++ objects with destructors across setjmp, and the callbacks never throw.
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string_view>

#include "storage/limits.hpp"
#include "storage/png_codec.hpp"
#include "storage/png_codec_detail.hpp"

namespace vimg {

namespace png_detail {

namespace {

extern "C" void on_png_read(png_structp png, png_bytep out, png_size_t length) {
  auto* source = static_cast<ReadSource*>(png_get_io_ptr(png));
  if (length > source->size - source->offset) png_error(png, "the file ends too early");
  std::memcpy(out, source->data + source->offset, length);
  source->offset += length;
}

// Text chunks are read by read_vibroimage_text(); libpng skips them.
constexpr png_byte kTextChunks[] = {'t', 'E', 'X', 't', '\0', 'z', 'T', 'X', 't', '\0', 'i', 'T', 'X', 't', '\0'};

}  // namespace

bool decode_text(ReadState* state, ErrorSink* sink) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, sink, on_png_error, on_png_warning);
  if (png == nullptr) {
    std::snprintf(sink->message, sizeof sink->message, "cannot create a PNG decoder");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    std::snprintf(sink->message, sizeof sink->message, "cannot create a PNG decoder");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_read_fn(png, &state->source, on_png_read);
#ifdef VIMG_FUZZING
  // Fuzzing only: accept wrong CRCs so that mutated chunk contents reach the decoders.
  png_set_crc_action(png, PNG_CRC_QUIET_USE, PNG_CRC_QUIET_USE);
#endif
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, kTextChunks, 3);
  png_set_user_limits(png, kMaxPngSide, kMaxPngSide);
  png_set_chunk_malloc_max(png, kMaxImageFileBytes + 1024 * 1024);
  png_read_info(png, info);
  const double pixels = static_cast<double>(png_get_image_width(png, info)) *
                        static_cast<double>(png_get_image_height(png, info));
  if (pixels > state->max_pixels) png_error(png, "the picture is too large to decode");
  if (state->keep_pixels) {  // every colour type and depth as 8-bit RGBA
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
  }
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const png_size_t row_bytes = png_get_rowbytes(png, info);
  state->row = static_cast<unsigned char*>(std::malloc(row_bytes == 0 ? 1 : row_bytes));
  if (state->row == nullptr) png_error(png, "out of memory");
  const png_uint_32 height = png_get_image_height(png, info);
  if (state->keep_pixels) {
    state->width = png_get_image_width(png, info);
    state->height = height;
    if (state->pixels == nullptr || row_bytes * height > state->pixel_bytes) png_error(png, "the picture is larger than its header said");
  }
  for (int pass = 0; pass < passes; ++pass) {
    for (png_uint_32 y = 0; y < height; ++y) {
      png_read_row(png, state->keep_pixels ? state->pixels + row_bytes * y : state->row, nullptr);
    }
  }
  png_read_end(png, info);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace png_detail

namespace {

using png_detail::be32;
using png_detail::chunk_lengths_fit;
using png_detail::decode_text;
using png_detail::ErrorSink;
using png_detail::ReadState;

}  // namespace

DecodedPng decode_png_rgba(std::string_view bytes, double max_pixels) {
  DecodedPng result;
  ErrorSink sink;
  if (!chunk_lengths_fit(bytes, &sink)) {
    result.error = sink.message;
    return result;
  }
  if (auto limit = png_detail::size_problem(bytes, max_pixels)) {
    result.error = *limit;
    return result;
  }
  if (auto over = png_detail::image_data_over_rows(bytes)) {
    result.error = *over;
    return result;
  }
  // The pixels as IHDR declares them, decoded in place (within the limits just checked).
  // (Without IHDR first there is nothing to hold: libpng refuses such a file before the rows.)
  const bool ihdr_first = bytes.size() >= 24 && bytes.compare(12, 4, "IHDR") == 0;
  const std::size_t declared = ihdr_first ? std::size_t{be32(bytes, 16)} * be32(bytes, 20) * 4 : 0;
  try {
    result.rgba.resize(declared);
  } catch (const std::bad_alloc&) {
    result.error = "out of memory decoding the picture";
    return result;
  }
  ReadState state;
  state.source.data = reinterpret_cast<const unsigned char*>(bytes.data());
  state.source.size = bytes.size();
  state.keep_pixels = true;
  state.max_pixels = max_pixels;
  state.pixels = result.rgba.data();
  state.pixel_bytes = result.rgba.size();
  const bool decoded = decode_text(&state, &sink);
  std::free(state.row);
  if (!decoded) {
    result.rgba = {};
    result.error = sink.message;
    return result;
  }
  result.width = static_cast<int>(state.width);
  result.height = static_cast<int>(state.height);
  return result;
}

}  // namespace vimg
