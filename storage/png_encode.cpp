// PNG encoding with libpng: the RGB rows (Up filter, zlib RLE), the pHYs chunk and the compressed
// `vibroimage` iTXt chunk. libpng reports errors by longjmp: encode_into() holds no C++ objects
// with destructors across setjmp, and the callbacks never throw.
#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>

#include "storage/png_codec.hpp"
#include "storage/png_codec_detail.hpp"

namespace vimg {

namespace {

using png_detail::ErrorSink;
using png_detail::on_png_error;
using png_detail::on_png_warning;

struct WriteTarget {
  std::string* out = nullptr;
  bool out_of_memory = false;
};

extern "C" void on_png_write(png_structp png, png_bytep data, png_size_t length) {
  auto* target = static_cast<WriteTarget*>(png_get_io_ptr(png));
  try {
    target->out->append(reinterpret_cast<const char*>(data), length);
  } catch (...) {
    target->out_of_memory = true;
  }
  if (target->out_of_memory) png_error(png, "out of memory while encoding");
}

extern "C" void on_png_flush(png_structp) {}

// Returns true on success; on failure `sink` holds the reason. No C++ objects live here.
bool encode_into(const RgbRaster& raster, std::uint32_t pixels_per_metre, char* xml_text, WriteTarget* target,
                 ErrorSink* sink) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, sink, on_png_error, on_png_warning);
  if (png == nullptr) {
    std::snprintf(sink->message, sizeof sink->message, "cannot create a PNG encoder");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(sink->message, sizeof sink->message, "cannot create a PNG encoder");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, target, on_png_write, on_png_flush);
  // Speed over size (docs/benchmarks.md): each row as its difference from the row above (the
  // "Up" filter: flat colour and vertical stripes become runs of zeros) packed by zlib's run-length
  // strategy, which only looks for repeats of the previous byte. On the 100 000-primitive
  // benchmark picture this is smaller (15 MB against 21 MB) and about twice as fast as level 1 on
  // unfiltered rows. The XML text at zlib's fastest level.
  png_set_compression_level(png, 1);
  png_set_compression_strategy(png, Z_RLE);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_text_compression_level(png, 1);
  png_set_IHDR(png, info, static_cast<png_uint_32>(raster.width), static_cast<png_uint_32>(raster.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_pHYs(png, info, pixels_per_metre, pixels_per_metre, PNG_RESOLUTION_METER);
  png_text text;
  std::memset(&text, 0, sizeof text);
  text.compression = PNG_ITXT_COMPRESSION_zTXt;
  text.key = const_cast<png_charp>(kPngTextKeyword.data());
  text.text = xml_text;
  text.lang = nullptr;
  text.lang_key = nullptr;
  png_set_text(png, info, &text, 1);
  png_write_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(raster.width) * 3;
  for (int y = 0; y < raster.height; ++y) {
    png_write_row(png, raster.rgb.data() + static_cast<std::size_t>(y) * stride);
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

EncodedPng encode_png(const RgbRaster& raster, std::uint32_t pixels_per_metre, const std::string& xml) {
  EncodedPng result;
  WriteTarget target;
  target.out = &result.bytes;
  // Room for the worst case (pixels and text that do not compress), so that appending never
  // copies what is already written; pages that are never written are never touched.
  try {
    result.bytes.reserve(raster.rgb.size() + static_cast<std::size_t>(raster.height) + xml.size() + 65536);
  } catch (const std::bad_alloc&) {
  }
  ErrorSink sink;
  // libpng reads the text through a non-const pointer but never writes it.
  if (!encode_into(raster, pixels_per_metre, const_cast<char*>(xml.c_str()), &target, &sink)) {
    result.bytes.clear();
    result.error = std::string("cannot encode PNG: ") + sink.message;
  }
  return result;
}

}  // namespace vimg
