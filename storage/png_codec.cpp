// Shared by the PNG files: the libpng error callbacks, the walk over the chunk lengths of the raw
// bytes, big-endian numbers, and the PNG signature test.
#include "storage/png_codec.hpp"

#include <png.h>

#include <cstdio>
#include <string_view>

#include "storage/png_codec_detail.hpp"

namespace vimg {

namespace png_detail {

extern "C" void on_png_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", message != nullptr ? message : "unknown libpng error");
  png_longjmp(png, 1);
}

extern "C" void on_png_warning(png_structp, png_const_charp) {}

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

}  // namespace png_detail

bool looks_like_png(std::string_view bytes) {
  return bytes.size() >= 8 && png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0;
}

}  // namespace vimg
