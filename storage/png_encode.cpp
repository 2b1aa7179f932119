// PNG encoding (spec section 2, docs/format-png.md "PNG"): the signature, IHDR, pHYs, the compressed
// `vibroimage` iTXt chunk, the pixels in IDAT chunks, IEND. The chunks are framed here rather than
// by libpng because libpng compresses the pixels as one stream on one thread: here the picture is
// drawn, filtered and compressed band by band, and the XML text written and compressed in parts,
// on several threads at once (storage/parallel_tasks.hpp, storage/deflate_parts.hpp). The bytes
// do not depend on the number of threads.
//
// Pixels: each band's first row is filtered with PNG's "Sub" filter (it needs no row above, which
// another thread may still be drawing), the others with "Up" (flat colour and vertical stripes
// become zeros). zlib then only Huffman-codes the bytes: on the 100 000-primitive benchmark picture
// that is 2 % bigger than its run-length strategy and 20 % faster (docs/benchmarks/storage.md). One IDAT
// chunk per band. The XML text: zlib level 1 in parts of at least 1 MiB.
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <latch>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "storage/deflate_parts.hpp"
#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/parallel_tasks.hpp"
#include "storage/png_codec.hpp"

namespace vimg {

namespace {

constexpr DeflateSettings kPixelDeflate{1, Z_HUFFMAN_ONLY, 9};
constexpr DeflateSettings kTextDeflate{1, Z_DEFAULT_STRATEGY};
constexpr std::size_t kMinTextPartBytes = kMiB;
constexpr std::size_t kMaxTextParts = 64;
constexpr std::uint8_t kFilterSub = 1;
constexpr std::uint8_t kFilterUp = 2;

void append_be32(std::string& out, std::uint32_t value) {
  const std::array<char, 4> bytes = {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                                     static_cast<char>(value >> 8), static_cast<char>(value)};
  out.append(bytes.data(), bytes.size());
}

void put_be32(std::string& out, std::size_t pos, std::uint32_t value) {
  out[pos] = static_cast<char>(value >> 24);
  out[pos + 1] = static_cast<char>(value >> 16);
  out[pos + 2] = static_cast<char>(value >> 8);
  out[pos + 3] = static_cast<char>(value);
}

std::uint32_t crc_of(std::uint32_t crc, std::string_view bytes) {
  return static_cast<std::uint32_t>(crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

void append_chunk(std::string& out, std::string_view type, std::string_view data) {
  append_be32(out, static_cast<std::uint32_t>(data.size()));
  out.append(type);
  out.append(data);
  append_be32(out, crc_of(crc_of(0, type), data));
}

// The start of the iTXt chunk: keyword, compressed, method 0, no language, no translated keyword.
std::string text_chunk_prefix() {
  std::string prefix(kPngTextKeyword);
  prefix += std::string_view("\0\1\0\0\0", 5);
  return prefix;
}

// Filters a band's scanlines in place (each is a filter byte and 3 * width bytes): the first row
// by Sub, the others by Up. Rows are done last to first, and each row right to left, so every
// byte is read before it is changed.
void filter_band(std::uint8_t* band, int rows, std::size_t row_bytes) {
  const std::size_t stride = row_bytes + 1;
  for (int r = rows - 1; r >= 1; --r) {
    std::uint8_t* row = band + static_cast<std::size_t>(r) * stride;
    const std::uint8_t* above = row - stride;
    row[0] = kFilterUp;
    for (std::size_t i = 1; i <= row_bytes; ++i) row[i] = static_cast<std::uint8_t>(row[i] - above[i]);
  }
  band[0] = kFilterSub;
  for (std::size_t i = row_bytes; i > 3; --i) band[i] = static_cast<std::uint8_t>(band[i] - band[i - 3]);
}

// One IDAT chunk in the making: length and type first (the length patched at the end), then the
// band's compressed data.
struct PixelChunk {
  std::string bytes;
  DeflatedPart part;
  std::uint32_t crc = 0;  // of the type and the data so far
};

// Memory each thread reuses from one task to the next: a band's scanlines, and compressed bytes
// before they are copied out at their final size (zlib wants room for the worst case, which would
// otherwise be allocated and touched for every band).
struct Scratch {
  std::vector<std::uint8_t> rows;
  std::string compressed;
};

struct TextPart {
  std::string bytes;
  DeflatedPart part;
  std::uint32_t crc = 0;
};

class Encoder {
 public:
  Encoder(const PngSource& source, int threads) : source_(source), threads_(worker_thread_count(threads)) {}

  PngPieces run() {
    PngPieces result;
    const int bands = (source_.height_px + source_.band_rows - 1) / source_.band_rows;
    chunks_.resize(static_cast<std::size_t>(bands));
    text_parts_.resize(kMaxTextParts);
    scratch_.resize(static_cast<std::size_t>(threads_));
    // Task 0 writes the XML; then the bands; then the parts of the text, which wait for task 0
    // (claimed first, so it is running or done by then).
    const std::size_t tasks = 1 + static_cast<std::size_t>(bands) + kMaxTextParts;
    try {
      run_tasks(tasks, threads_, [&](std::size_t index, int worker) {
        if (index == 0) {
          write_text();
        } else if (index <= static_cast<std::size_t>(bands)) {
          encode_band(static_cast<int>(index - 1), scratch_[static_cast<std::size_t>(worker)]);
        } else {
          compress_text_part(index - 1 - static_cast<std::size_t>(bands), scratch_[static_cast<std::size_t>(worker)]);
        }
      });
      if (!text_error_.empty()) {
        result.error = text_error_;
        return result;
      }
      assemble(result.pieces);
    } catch (const std::bad_alloc&) {
      result.pieces.clear();
      result.error = "cannot encode PNG: out of memory";
    } catch (const std::exception& e) {
      result.pieces.clear();
      result.error = std::string("cannot encode PNG: ") + e.what();
    }
    return result;
  }

 private:
  void write_text() {
    // Whatever happens here, the text parts waiting for it go on (and find no text).
    struct Release {
      std::latch& latch;
      ~Release() { latch.count_down(); }
    } release{text_ready_};
    text_ = source_.xml();
    if (auto error = saved_text_error(text_)) {
      text_error_ = std::move(*error);
      return;
    }
    text_part_bytes_ = std::max(kMinTextPartBytes, (text_.size() + kMaxTextParts - 1) / kMaxTextParts);
    text_part_count_ = std::max<std::size_t>(1, (text_.size() + text_part_bytes_ - 1) / text_part_bytes_);
    text_ok_ = true;
  }

  void compress_text_part(std::size_t j, Scratch& scratch) {
    text_ready_.wait();
    if (!text_ok_ || j >= text_part_count_) return;
    const std::size_t begin = j * text_part_bytes_;
    const std::size_t end = std::min(text_.size(), begin + text_part_bytes_);
    const auto* data = reinterpret_cast<const std::uint8_t*>(text_.data());
    TextPart& part = text_parts_[j];
    scratch.compressed.clear();
    part.part = deflate_part({data + begin, end - begin}, kTextDeflate, j + 1 == text_part_count_, scratch.compressed);
    part.bytes = scratch.compressed;
    part.crc = crc_of(0, part.bytes);
  }

  void encode_band(int band, Scratch& scratch) {
    const int first_row = band * source_.band_rows;
    const int rows = std::min(source_.band_rows, source_.height_px - first_row);
    const std::size_t row_bytes = static_cast<std::size_t>(source_.width_px) * 3;
    scratch.rows.resize(static_cast<std::size_t>(rows) * (row_bytes + 1));
    source_.draw_band(band, scratch.rows.data() + 1, row_bytes + 1);
    filter_band(scratch.rows.data(), rows, row_bytes);
    const bool last = static_cast<std::size_t>(band) + 1 == chunks_.size();
    scratch.compressed.clear();
    if (band == 0) {
      const auto header = zlib_header(kPixelDeflate.level);
      scratch.compressed.append(reinterpret_cast<const char*>(header.data()), header.size());
    }
    PixelChunk& chunk = chunks_[static_cast<std::size_t>(band)];
    chunk.part = deflate_part(scratch.rows, kPixelDeflate, last, scratch.compressed);
    // Length (patched when assembled), type, data, and room for the zlib trailer and the CRC.
    chunk.bytes.reserve(8 + scratch.compressed.size() + 8);
    chunk.bytes.assign(4, '\0');
    chunk.bytes += "IDAT";
    chunk.bytes += scratch.compressed;
    chunk.crc = crc_of(0, std::string_view(chunk.bytes).substr(4));
  }

  void assemble(std::vector<std::string>& pieces) {
    // Signature, IHDR, pHYs, and the iTXt chunk up to its first compressed part.
    std::string head("\x89PNG\r\n\x1a\n", 8);
    std::string ihdr;
    append_be32(ihdr, static_cast<std::uint32_t>(source_.width_px));
    append_be32(ihdr, static_cast<std::uint32_t>(source_.height_px));
    ihdr += std::string_view("\x08\x02\x00\x00\x00", 5);  // 8-bit RGB, deflate, adaptive filters, no interlace
    append_chunk(head, "IHDR", ihdr);
    std::string phys;
    append_be32(phys, source_.pixels_per_metre);
    append_be32(phys, source_.pixels_per_metre);
    phys += '\x01';  // metre
    append_chunk(head, "pHYs", phys);

    std::string text_start = text_chunk_prefix();
    const auto header = zlib_header(kTextDeflate.level);
    text_start.append(reinterpret_cast<const char*>(header.data()), header.size());
    std::size_t text_length = text_start.size() + 4;
    std::uint32_t crc = crc_of(crc_of(0, "iTXt"), text_start);
    std::uint32_t adler = 1;
    for (std::size_t j = 0; j < text_part_count_; ++j) {
      const TextPart& part = text_parts_[j];
      text_length += part.bytes.size();
      crc = static_cast<std::uint32_t>(crc32_combine64(crc, part.crc, static_cast<z_off64_t>(part.bytes.size())));
      adler = combine_adler(adler, part.part.adler, part.part.raw_bytes);
    }
    append_be32(head, static_cast<std::uint32_t>(text_length));
    head += "iTXt";
    head += text_start;
    pieces.push_back(std::move(head));
    for (std::size_t j = 0; j < text_part_count_; ++j) pieces.push_back(std::move(text_parts_[j].bytes));
    std::string text_end;
    const auto trailer = zlib_trailer(adler);
    text_end.append(reinterpret_cast<const char*>(trailer.data()), trailer.size());
    append_be32(text_end, crc_of(crc, text_end));
    pieces.push_back(std::move(text_end));

    // The IDAT chunks; the last one ends the pixels' zlib stream.
    std::uint32_t pixel_adler = 1;
    for (const PixelChunk& chunk : chunks_) pixel_adler = combine_adler(pixel_adler, chunk.part.adler, chunk.part.raw_bytes);
    for (std::size_t b = 0; b < chunks_.size(); ++b) {
      PixelChunk& chunk = chunks_[b];
      if (b + 1 == chunks_.size()) {
        const auto end = zlib_trailer(pixel_adler);
        const std::string_view end_bytes(reinterpret_cast<const char*>(end.data()), end.size());
        chunk.bytes.append(end_bytes);
        chunk.crc = crc_of(chunk.crc, end_bytes);
      }
      put_be32(chunk.bytes, 0, static_cast<std::uint32_t>(chunk.bytes.size() - 8));
      append_be32(chunk.bytes, chunk.crc);
      pieces.push_back(std::move(chunk.bytes));
    }
    std::string end;
    append_chunk(end, "IEND", "");
    pieces.push_back(std::move(end));
  }

  const PngSource& source_;
  const int threads_;
  std::vector<PixelChunk> chunks_;
  std::vector<Scratch> scratch_;  // one per thread
  std::latch text_ready_{1};
  std::string text_;
  std::string text_error_;
  bool text_ok_ = false;
  std::size_t text_part_bytes_ = kMinTextPartBytes;
  std::size_t text_part_count_ = 0;
  std::vector<TextPart> text_parts_;
};

}  // namespace

std::size_t PngPieces::size() const {
  std::size_t bytes = 0;
  for (const std::string& piece : pieces) bytes += piece.size();
  return bytes;
}

PngPieces encode_png_pieces(const PngSource& source, int threads) {
  if (source.width_px <= 0 || source.height_px <= 0 || source.band_rows <= 0 || !source.draw_band || !source.xml) {
    PngPieces result;
    result.error = "cannot encode PNG: no picture";
    return result;
  }
  return Encoder(source, threads).run();
}

EncodedPng encode_png(const RgbRaster& raster, std::uint32_t pixels_per_metre, const std::string& xml) {
  PngSource source;
  source.width_px = raster.width;
  source.height_px = raster.height;
  source.pixels_per_metre = pixels_per_metre;
  const std::size_t row_bytes = static_cast<std::size_t>(raster.width) * 3;
  source.draw_band = [&](int band, std::uint8_t* first_row, std::size_t stride) {
    const int row0 = band * source.band_rows;
    const int rows = std::min(source.band_rows, raster.height - row0);
    for (int r = 0; r < rows; ++r) std::memcpy(first_row + static_cast<std::size_t>(r) * stride, raster.pixel(0, row0 + r), row_bytes);
  };
  source.xml = [&] { return xml; };
  PngPieces pieces = encode_png_pieces(source, 1);
  EncodedPng result;
  result.error = std::move(pieces.error);
  if (!result.error.empty()) return result;
  result.bytes.reserve(pieces.size());
  for (const std::string& piece : pieces.pieces) result.bytes += piece;
  return result;
}

}  // namespace vimg
