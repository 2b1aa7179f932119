#include "storage/deflate_parts.hpp"

#include <zlib.h>

#include <limits>
#include <new>
#include <stdexcept>

namespace vimg {

namespace {

// zlib's z_stream counts in uInt: a part bigger than that is fed in pieces.
constexpr std::size_t kMaxFeed = std::numeric_limits<uInt>::max() / 2;

[[noreturn]] void fail(int code, const char* what) {
  if (code == Z_MEM_ERROR) throw std::bad_alloc();
  throw std::runtime_error(std::string("zlib cannot ") + what + " (error " + std::to_string(code) + ")");
}

class RawDeflater {
 public:
  explicit RawDeflater(const DeflateSettings& settings) {
    const int code = deflateInit2(&stream_, settings.level, Z_DEFLATED, -15, settings.mem_level, settings.strategy);
    if (code != Z_OK) fail(code, "start compressing");
  }
  ~RawDeflater() { deflateEnd(&stream_); }
  RawDeflater(const RawDeflater&) = delete;
  RawDeflater& operator=(const RawDeflater&) = delete;
  z_stream& stream() { return stream_; }

 private:
  z_stream stream_{};
};

}  // namespace

DeflatedPart deflate_part(std::span<const std::uint8_t> raw, const DeflateSettings& settings, bool last,
                          std::string& out) {
  DeflatedPart part;
  part.first_byte = out.size();
  part.raw_bytes = raw.size();
  RawDeflater deflater(settings);
  z_stream& z = deflater.stream();
  // Room for the whole part at once (deflateBound, plus the sync flush's empty block); grown when a
  // flush needs more.
  out.resize(part.first_byte + deflateBound(&z, static_cast<uLong>(std::min(raw.size(), kMaxFeed))) + 64);
  std::size_t written = part.first_byte;
  std::size_t fed = 0;
  for (;;) {
    const std::size_t feed = std::min(raw.size() - fed, kMaxFeed);
    z.next_in = const_cast<Bytef*>(raw.data() + fed);  // zlib never writes its input
    z.avail_in = static_cast<uInt>(feed);
    const bool final_feed = fed + feed == raw.size();
    const int flush = !final_feed ? Z_NO_FLUSH : (last ? Z_FINISH : Z_SYNC_FLUSH);
    for (;;) {
      if (out.size() - written < 64) out.resize(out.size() + out.size() / 2 + 4096);
      const std::size_t room = std::min(out.size() - written, kMaxFeed);
      z.next_out = reinterpret_cast<Bytef*>(out.data() + written);
      z.avail_out = static_cast<uInt>(room);
      const int code = deflate(&z, flush);
      written += room - z.avail_out;
      if (code == Z_STREAM_END) break;
      if (code != Z_OK && code != Z_BUF_ERROR) fail(code, "compress");
      // Done with this feed when zlib took all input and, for a flush, left output room unused.
      if (z.avail_in == 0 && z.avail_out != 0) break;
    }
    fed += feed;
    if (final_feed) break;
  }
  out.resize(written);
  part.adler = static_cast<std::uint32_t>(adler32_z(1, raw.data(), raw.size()));
  return part;
}

std::array<std::uint8_t, 2> zlib_header(int level) {
  // CMF: deflate with a 32 KiB window. FLG: the level class, no dictionary, and the check bits that
  // make CMF * 256 + FLG a multiple of 31.
  const std::uint8_t cmf = 0x78;
  const int level_class = level <= 1 ? 0 : level <= 5 ? 1 : level == 6 ? 2 : 3;
  int flg = level_class << 6;
  flg += (31 - (cmf * 256 + flg) % 31) % 31;
  return {cmf, static_cast<std::uint8_t>(flg)};
}

std::uint32_t combine_adler(std::uint32_t first, std::uint32_t second, std::size_t second_raw_bytes) {
  return static_cast<std::uint32_t>(adler32_combine64(first, second, static_cast<z_off64_t>(second_raw_bytes)));
}

std::array<std::uint8_t, 4> zlib_trailer(std::uint32_t adler) {
  return {static_cast<std::uint8_t>(adler >> 24), static_cast<std::uint8_t>(adler >> 16),
          static_cast<std::uint8_t>(adler >> 8), static_cast<std::uint8_t>(adler)};
}

}  // namespace vimg
