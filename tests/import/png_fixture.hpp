#pragma once
// Plain PNG files for the picture-import tests, written here (8-bit grey, RGB or RGBA, no text
// chunks) so that the tests do not depend on the code under test to make their input.
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vimg::test {

inline void put_be32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((v >> shift) & 0xff));
}

inline void put_chunk(std::string& out, const char* type, const std::string& data) {
  put_be32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put_be32(out, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

// `channels`: 1 grey, 3 RGB, 4 RGBA; `pixels` rows top to bottom.
inline std::string make_png(int width, int height, int channels, const std::vector<std::uint8_t>& pixels) {
  std::string out = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  put_be32(ihdr, static_cast<std::uint32_t>(width));
  put_be32(ihdr, static_cast<std::uint32_t>(height));
  const char colour_type = channels == 1 ? 0 : channels == 3 ? 2 : 6;
  ihdr += std::string{8, colour_type, 0, 0, 0};
  put_chunk(out, "IHDR", ihdr);
  std::string raw;
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);  // filter: none
    raw.append(reinterpret_cast<const char*>(pixels.data()) + static_cast<std::size_t>(y) * width * channels,
               static_cast<std::size_t>(width) * channels);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string z(size, '\0');
  compress(reinterpret_cast<Bytef*>(z.data()), &size, reinterpret_cast<const Bytef*>(raw.data()), static_cast<uLong>(raw.size()));
  z.resize(size);
  put_chunk(out, "IDAT", z);
  put_chunk(out, "IEND", "");
  return out;
}

}  // namespace vimg::test
