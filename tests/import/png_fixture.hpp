#pragma once
// Plain PNG files for the picture-import tests, written here (8-bit grey, RGB or RGBA, no text
// chunks) so that the tests do not depend on the code under test to make their input.
#include <zlib.h>

#include <cstdint>
#include <random>
#include <string>
#include <utility>
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

// A PNG whose header says `width` x `height` at 8 bits (colour type 0 grey, 2 RGB, 6 RGBA) and whose
// one IDAT chunk holds `idat` as given: the bounds tests give data that does not match the header.
inline std::string png_with_idat(std::uint32_t width, std::uint32_t height, char colour_type, const std::string& idat) {
  std::string out = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  put_be32(ihdr, width);
  put_be32(ihdr, height);
  ihdr += std::string{8, colour_type, 0, 0, 0};
  put_chunk(out, "IHDR", ihdr);
  put_chunk(out, "IDAT", idat);
  put_chunk(out, "IEND", "");
  return out;
}

// `channels`: 1 grey, 3 RGB, 4 RGBA; `pixels` rows top to bottom.
inline std::string make_png(int width, int height, int channels, const std::vector<std::uint8_t>& pixels) {
  const char colour_type = channels == 1 ? 0 : channels == 3 ? 2 : 6;
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
  return png_with_idat(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), colour_type, z);
}

// A maze of one-pixel walls and corridors on an odd `side` (a depth-first carve from the top-left
// cell, directions drawn from mt19937(seed)): true where a pixel is corridor. Its outline turns at
// nearly every other pixel.
inline std::vector<bool> maze_corridors(int side, unsigned seed) {
  const auto index = [side](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x); };
  std::vector<bool> corridor(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), false);
  const int cells = (side - 1) / 2;
  std::vector<bool> seen(static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells), false);
  std::mt19937 rng(seed);
  std::vector<std::pair<int, int>> path = {{0, 0}};
  seen[0] = true;
  corridor[index(1, 1)] = true;
  constexpr int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  while (!path.empty()) {
    const auto [cx, cy] = path.back();
    int ways[4], count = 0;
    for (int d = 0; d < 4; ++d) {
      const int nx = cx + kSteps[d][0], ny = cy + kSteps[d][1];
      if (nx >= 0 && ny >= 0 && nx < cells && ny < cells && !seen[static_cast<std::size_t>(ny * cells + nx)]) ways[count++] = d;
    }
    if (count == 0) {
      path.pop_back();
      continue;
    }
    const int d = ways[rng() % static_cast<unsigned>(count)];
    const int nx = cx + kSteps[d][0], ny = cy + kSteps[d][1];
    seen[static_cast<std::size_t>(ny * cells + nx)] = true;
    corridor[index(2 * cx + 1 + kSteps[d][0], 2 * cy + 1 + kSteps[d][1])] = true;
    corridor[index(2 * nx + 1, 2 * ny + 1)] = true;
    path.push_back({nx, ny});
  }
  return corridor;
}

}  // namespace vimg::test
