#include "storage/volume/inflate_count.hpp"

#include <bzlib.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <limits>

namespace vimg {
namespace {

constexpr std::size_t kBuffer = 1 << 16;
constexpr std::size_t kMaxFeed = std::numeric_limits<unsigned>::max();

InflateCount count_gzip(std::string_view input, std::size_t limit) {
  InflateCount result;
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK) {  // gzip or zlib header
    result.problem = "cannot start the gzip decoder";
    return result;
  }
  std::array<char, kBuffer> buffer{};
  int status = Z_OK;
  while (status == Z_OK && result.bytes <= limit) {
    if (z.avail_in == 0 && !input.empty()) {
      const std::size_t feed = std::min(input.size(), kMaxFeed);
      z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(input.data()));
      z.avail_in = static_cast<uInt>(feed);
      input.remove_prefix(feed);
    }
    const std::size_t room = std::min(kBuffer, limit + 1 - result.bytes);
    z.next_out = reinterpret_cast<Bytef*>(buffer.data());
    z.avail_out = static_cast<uInt>(room);
    status = ::inflate(&z, Z_NO_FLUSH);
    result.bytes += room - z.avail_out;
    if (status == Z_BUF_ERROR && z.avail_in == 0 && input.empty()) {
      result.problem = "gzip data is truncated";
    } else if (status == Z_BUF_ERROR) {
      status = Z_OK;
    } else if (status != Z_OK && status != Z_STREAM_END) {
      result.problem = std::string("gzip data is corrupt (") + (z.msg ? z.msg : "zlib error") + ")";
    }
  }
  inflateEnd(&z);
  return result;
}

InflateCount count_bzip2(std::string_view input, std::size_t limit) {
  InflateCount result;
  bz_stream b{};
  if (BZ2_bzDecompressInit(&b, 0, 0) != BZ_OK) {
    result.problem = "cannot start the bzip2 decoder";
    return result;
  }
  std::array<char, kBuffer> buffer{};
  int status = BZ_OK;
  while (status == BZ_OK && result.bytes <= limit) {
    if (b.avail_in == 0 && !input.empty()) {
      const std::size_t feed = std::min(input.size(), kMaxFeed);
      b.next_in = const_cast<char*>(input.data());
      b.avail_in = static_cast<unsigned>(feed);
      input.remove_prefix(feed);
    }
    const std::size_t room = std::min(kBuffer, limit + 1 - result.bytes);
    b.next_out = buffer.data();
    b.avail_out = static_cast<unsigned>(room);
    status = BZ2_bzDecompress(&b);
    const std::size_t produced = room - b.avail_out;
    result.bytes += produced;
    if (status == BZ_OK && produced == 0 && b.avail_in == 0 && input.empty()) {
      result.problem = "bzip2 data is truncated";
      break;
    } else if (status != BZ_OK && status != BZ_STREAM_END) {
      result.problem = "bzip2 data is corrupt (error " + std::to_string(status) + ")";
    }
  }
  BZ2_bzDecompressEnd(&b);
  return result;
}

}  // namespace

InflateCount count_inflated(std::string_view compressed, Compression compression, std::size_t limit) {
  return compression == Compression::gzip ? count_gzip(compressed, limit) : count_bzip2(compressed, limit);
}

}  // namespace vimg
