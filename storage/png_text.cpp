// Reading the `vibroimage` text chunk of a PNG: the size and image data limits (png_image_data.cpp), the iTXt/zTXt/tEXt
// chunks found by walking the bytes (with their CRC), inflation up to kMaxImageFileBytes, and
// read_png_text().
#include <zlib.h>

#include <cstdlib>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/limits.hpp"
#include "storage/png_codec.hpp"
#include "storage/png_codec_detail.hpp"

namespace vimg {

namespace {

using png_detail::be32;
using png_detail::chunk_lengths_fit;
using png_detail::decode_text;
using png_detail::ErrorSink;
using png_detail::ReadState;
using png_detail::image_data_over_rows;
using png_detail::size_problem;

// A text chunk whose keyword is `vibroimage`.
struct TextChunk {
  std::string_view type;  // tEXt, zTXt or iTXt
  std::string_view data;  // after the keyword and its NUL
  bool crc_ok = true;
};

// Every vibroimage text chunk before IEND (chunk_lengths_fit() has checked the lengths).
std::vector<TextChunk> vibroimage_chunks(std::string_view bytes) {
  std::vector<TextChunk> found;
  png_detail::for_each_chunk(bytes, [&](const png_detail::RawChunk& c) {
    const std::string_view data = c.data;
    if ((c.type == "tEXt" || c.type == "zTXt" || c.type == "iTXt") && data.size() > kPngTextKeyword.size() &&
        data.substr(0, kPngTextKeyword.size()) == kPngTextKeyword && data[kPngTextKeyword.size()] == '\0') {
      const std::string_view typed = bytes.substr(c.pos + 4, 4 + data.size());
      const auto crc = static_cast<std::uint32_t>(
          crc32(0, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size())));
      found.push_back({c.type, data.substr(kPngTextKeyword.size() + 1), crc == be32(bytes, c.pos + 8 + data.size())});
    }
    return true;
  });
  return found;
}

}  // namespace

std::optional<double> png_physical_width_mm(std::string_view bytes) {
  if (!looks_like_png(bytes)) return std::nullopt;
  std::optional<std::uint32_t> width_px;
  std::optional<double> width_mm;
  png_detail::for_each_chunk(bytes, [&](const png_detail::RawChunk& c) {
    if (c.type == "IHDR" && c.data.size() >= 4) width_px = be32(c.data, 0);
    if (c.type == "pHYs" && c.data.size() == 9 && width_px && *width_px > 0) {
      const std::uint32_t per_metre_x = be32(c.data, 0);
      const bool metre = c.data[8] == 1;
      if (!metre || per_metre_x == 0) return false;
      const double mm = 1000.0 * *width_px / per_metre_x;
      if (mm > 0.0 && mm <= kMaxCanvasMm) width_mm = mm;
      return false;
    }
    return c.type != "IDAT";  // pHYs comes before the pixels
  });
  return width_mm;
}

namespace {

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
  if (auto limit = size_problem(bytes, kMaxDecodedPngPixels)) {
    result.error = *limit;
    return result;
  }
  if (auto over = image_data_over_rows(bytes)) {
    result.error = *over;
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
