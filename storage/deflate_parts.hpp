#pragma once
// One zlib stream (RFC 1950) made of parts that are compressed independently, so that several
// threads can compress one stream at once (the PNG encoder's pixels and XML text).
//
// Each part is raw deflate data (RFC 1951). A part that is not the last ends with a sync flush: its
// blocks are not final and end on a byte boundary, so the next part's blocks may follow it
// directly. The stream is zlib_header() + the parts in order + zlib_trailer(the parts' Adler-32
// checksums combined). A part does not refer back into the parts before it, which costs a little
// compression at each boundary.
//
// Threads: deflate_part() is a pure function of its arguments and may run on many threads at once.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace vimg {

struct DeflateSettings {
  int level = 1;     // zlib's level, 0..9
  int strategy = 0;  // zlib's strategy (Z_DEFAULT_STRATEGY, Z_RLE, ...)
  int mem_level = 8;  // zlib's memLevel, 1..9: 9 makes longer blocks (fewer Huffman tables to build)
};

struct DeflatedPart {
  std::uint32_t adler = 1;      // Adler-32 of the raw bytes
  std::size_t raw_bytes = 0;    // how many raw bytes it holds
  std::size_t first_byte = 0;   // where its compressed bytes start in `out`
};

// Compresses `raw` as one part and appends it to `out`. `last` ends the stream (a final block).
// Throws std::bad_alloc when zlib has no memory and std::runtime_error on any other zlib error.
DeflatedPart deflate_part(std::span<const std::uint8_t> raw, const DeflateSettings& settings, bool last,
                          std::string& out);

// The two bytes that start a zlib stream compressed at `level`.
std::array<std::uint8_t, 2> zlib_header(int level);

// The Adler-32 of two parts' raw bytes one after the other, from theirs.
std::uint32_t combine_adler(std::uint32_t first, std::uint32_t second, std::size_t second_raw_bytes);

// The four bytes that end a zlib stream: the Adler-32 of all its raw bytes, big-endian.
std::array<std::uint8_t, 4> zlib_trailer(std::uint32_t adler);

}  // namespace vimg
