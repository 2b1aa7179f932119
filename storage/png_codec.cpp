// PNG encoding and decoding with libpng. libpng reports errors by longjmp: the functions that call
// setjmp hold no C++ objects with destructors across it, and the callbacks never throw.
#include "storage/png_codec.hpp"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "storage/limits.hpp"

namespace vimg {

namespace {

struct ErrorSink {
  char message[256] = {};
};

extern "C" void on_png_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message != nullptr ? message : "unknown libpng error");
  png_longjmp(png, 1);
}

extern "C" void on_png_warning(png_structp, png_const_charp) {}

// --- writing -------------------------------------------------------------------------------------

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

// --- reading -------------------------------------------------------------------------------------

struct ReadSource {
  const unsigned char* data = nullptr;
  std::size_t size = 0;
  std::size_t offset = 0;
};

extern "C" void on_png_read(png_structp png, png_bytep out, png_size_t length) {
  auto* source = static_cast<ReadSource*>(png_get_io_ptr(png));
  if (length > source->size - source->offset) png_error(png, "the file ends too early");
  std::memcpy(out, source->data + source->offset, length);
  source->offset += length;
}

struct ReadState {
  ReadSource source;
  unsigned char* row = nullptr;  // malloc'ed; freed by the caller on every path
  // decode_png_rgba only: the whole picture as 8-bit RGBA rows (malloc'ed, freed by the caller).
  bool keep_pixels = false;
  double max_pixels = kMaxDecodedPngPixels;
  unsigned char* pixels = nullptr;
  png_uint_32 width = 0;
  png_uint_32 height = 0;
};

// Text chunks are read by read_vibroimage_text(); libpng skips them.
constexpr png_byte kTextChunks[] = {'t', 'E', 'X', 't', '\0', 'z', 'T', 'X', 't', '\0', 'i', 'T', 'X', 't', '\0'};

// Returns true when the whole PNG decodes; no C++ objects live here.
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
    state->pixels = static_cast<unsigned char*>(std::malloc(row_bytes * height + 1));
    if (state->pixels == nullptr) png_error(png, "out of memory");
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

// libpng allocates a chunk's declared length before reading it; a chunk can never be longer than
// the bytes that follow it, so such lies are caught here, before any allocation.
bool chunk_lengths_fit(std::string_view bytes, ErrorSink* sink) {
  std::size_t pos = 8;
  while (pos + 8 <= bytes.size()) {
    const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])); };
    const std::uint32_t length = byte(pos) << 24 | byte(pos + 1) << 16 | byte(pos + 2) << 8 | byte(pos + 3);
    const std::size_t remaining = bytes.size() - pos - 8;
    if (length > remaining || remaining - length < 4) {
      std::snprintf(sink->message, sizeof sink->message, "the file ends too early (a chunk claims %u bytes)",
                    static_cast<unsigned>(length));
      return false;
    }
    if (bytes.compare(pos + 4, 4, "IEND") == 0) return true;
    pos += 12 + static_cast<std::size_t>(length);
  }
  return true;  // libpng reports the missing end itself
}

std::uint32_t be32(std::string_view bytes, std::size_t pos) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])); };
  return byte(pos) << 24 | byte(pos + 1) << 16 | byte(pos + 2) << 8 | byte(pos + 3);
}

// The picture's size from IHDR (the first chunk) against kMaxPngSide and kMaxDecodedPngPixels:
// a limit, not damage, and named with the size (libpng would only say "Invalid IHDR data").
std::optional<std::string> size_over_limits(std::string_view bytes) {
  if (bytes.size() < 24 || bytes.compare(12, 4, "IHDR") != 0) return std::nullopt;  // libpng reports it
  const std::uint32_t width = be32(bytes, 16), height = be32(bytes, 20);
  const std::string size = "the picture is " + std::to_string(width) + " x " + std::to_string(height) + " pixels";
  if (width > static_cast<std::uint32_t>(kMaxPngSide) || height > static_cast<std::uint32_t>(kMaxPngSide)) {
    return size + ", over the limit of " + std::to_string(kMaxPngSide) + " pixels a side (limit " +
           std::to_string(kMaxPngSide) + ")";
  }
  if (static_cast<double>(width) * static_cast<double>(height) > kMaxDecodedPngPixels) {
    const auto limit = std::to_string(static_cast<std::uint64_t>(kMaxDecodedPngPixels));
    return size + ", over the limit of " + limit + " pixels decoded (limit " + limit + ")";
  }
  return std::nullopt;
}

// A text chunk whose keyword is `vibroimage`.
struct TextChunk {
  std::string_view type;  // tEXt, zTXt or iTXt
  std::string_view data;  // after the keyword and its NUL
  bool crc_ok = true;
};

// Every vibroimage text chunk before IEND (chunk_lengths_fit() has checked the lengths).
std::vector<TextChunk> vibroimage_chunks(std::string_view bytes) {
  std::vector<TextChunk> found;
  std::size_t pos = 8;
  while (pos + 12 <= bytes.size()) {
    const std::uint32_t length = be32(bytes, pos);
    if (length > bytes.size() - pos - 12) break;
    const std::string_view type = bytes.substr(pos + 4, 4);
    if (type == "IEND") break;
    const std::string_view data = bytes.substr(pos + 8, length);
    if ((type == "tEXt" || type == "zTXt" || type == "iTXt") && data.size() > kPngTextKeyword.size() &&
        data.substr(0, kPngTextKeyword.size()) == kPngTextKeyword && data[kPngTextKeyword.size()] == '\0') {
      const std::string_view typed = bytes.substr(pos + 4, 4 + length);
      const auto crc = static_cast<std::uint32_t>(
          crc32(0, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size())));
      found.push_back({type, data.substr(kPngTextKeyword.size() + 1), crc == be32(bytes, pos + 8 + length)});
    }
    pos += 12 + static_cast<std::size_t>(length);
  }
  return found;
}

// Inflates zlib data into `out`, never past kMaxImageFileBytes + 1 bytes. Returns the problem, or
// an empty string.
std::string inflate_text(std::string_view compressed, std::string& out) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return "cannot start the zlib decoder";
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  z.avail_in = static_cast<uInt>(compressed.size());
  std::string problem;
  char buffer[65536];
  int status = Z_OK;
  while (status == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    status = ::inflate(&z, Z_NO_FLUSH);
    const std::size_t produced = sizeof buffer - z.avail_out;
    if (out.size() + produced > kMaxImageFileBytes) {
      problem = "too large";
      break;
    }
    out.append(buffer, produced);
    if (status == Z_BUF_ERROR && z.avail_in == 0) {
      problem = "the compressed text ends too early";
      break;
    }
  }
  if (problem.empty() && status != Z_STREAM_END) problem = std::string("zlib: ") + (z.msg != nullptr ? z.msg : "bad data");
  inflateEnd(&z);
  return problem;
}

// The XML of the one vibroimage chunk, or why there is none.
void read_vibroimage_text(std::string_view bytes, PngText& result) {
  const std::vector<TextChunk> chunks = vibroimage_chunks(bytes);
  if (chunks.empty()) return;
  if (chunks.size() > 1) {
    result.error = "this PNG holds " + std::to_string(chunks.size()) + " '" + std::string(kPngTextKeyword) +
                   "' text chunks; a vibroimage has exactly one";
    return;
  }
  const TextChunk& c = chunks.front();
  const std::string what = "the '" + std::string(kPngTextKeyword) + "' " + std::string(c.type) + " chunk is damaged";
  const auto damage = [&](const std::string& why) {
    result.error = what + " (" + why + ")";
    result.damaged = true;
  };
#ifndef VIMG_FUZZING
  if (!c.crc_ok) return damage("CRC mismatch");
#endif
  std::string_view text = c.data;
  bool compressed = false;
  if (c.type == "zTXt") {
    if (text.empty() || text[0] != '\0') return damage("unknown compression method");
    text.remove_prefix(1);
    compressed = true;
  } else if (c.type == "iTXt") {
    if (text.size() < 2 || (text[0] != '\0' && text[0] != '\1') || text[1] != '\0') {
      return damage("bad compression flag or method");
    }
    compressed = text[0] == '\1';
    text.remove_prefix(2);
    for (int field = 0; field < 2; ++field) {  // language tag, translated keyword
      const std::size_t nul = text.find('\0');
      if (nul == std::string_view::npos) return damage("no end of its language tag or translated keyword");
      text.remove_prefix(nul + 1);
    }
  }
  std::string xml;
  if (compressed) {
    const std::string problem = inflate_text(text, xml);
    if (problem == "too large") {
      result.error = "the '" + std::string(kPngTextKeyword) + "' text of this PNG inflates to more than " +
                     std::to_string(kMaxImageFileBytes) + " bytes (limit " + std::to_string(kMaxImageFileBytes) + ")";
      return;
    }
    if (!problem.empty()) return damage(problem);
  } else {
    xml.assign(text);
  }
  // PNG text never holds a NUL (tEXt/zTXt are Latin-1 without NUL, iTXt UTF-8 without NUL).
  if (const std::size_t nul = xml.find('\0'); nul != std::string::npos) {
    return damage("a NUL byte at offset " + std::to_string(nul) + " of its text");
  }
  result.xml = std::move(xml);
}

}  // namespace

bool looks_like_png(std::string_view bytes) {
  return bytes.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0;
}

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

DecodedPng decode_png_rgba(std::string_view bytes, double max_pixels) {
  DecodedPng result;
  ReadState state;
  state.source.data = reinterpret_cast<const unsigned char*>(bytes.data());
  state.source.size = bytes.size();
  state.keep_pixels = true;
  state.max_pixels = max_pixels;
  ErrorSink sink;
  const bool decoded = chunk_lengths_fit(bytes, &sink) && decode_text(&state, &sink);
  std::free(state.row);
  if (!decoded) {
    std::free(state.pixels);
    result.error = sink.message;
    return result;
  }
  try {
    const std::size_t size = std::size_t{state.width} * state.height * 4;
    result.rgba.assign(state.pixels, state.pixels + size);
    result.width = static_cast<int>(state.width);
    result.height = static_cast<int>(state.height);
  } catch (const std::bad_alloc&) {
    result.error = "out of memory decoding the picture";
  }
  std::free(state.pixels);
  return result;
}

PngText read_png_text(std::string_view bytes) {
  PngText result;
  ReadState state;
  state.source.data = reinterpret_cast<const unsigned char*>(bytes.data());
  state.source.size = bytes.size();
  ErrorSink sink;
  if (!chunk_lengths_fit(bytes, &sink)) {
    result.error = sink.message;
    result.damaged = true;
    return result;
  }
  if (auto limit = size_over_limits(bytes)) {
    result.error = *limit;
    return result;
  }
  const bool decoded = decode_text(&state, &sink);
  std::free(state.row);
  if (!decoded) {
    result.error = sink.message;
    result.damaged = true;
    return result;
  }
  try {
    read_vibroimage_text(bytes, result);
  } catch (const std::bad_alloc&) {
    result = PngText{};
    result.error = "out of memory reading the vibroimage text";
  }
  return result;
}

}  // namespace vimg
