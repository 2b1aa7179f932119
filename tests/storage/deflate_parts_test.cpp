// One zlib stream from parts compressed independently (storage/deflate_parts.hpp): whatever the
// cut points, the settings and the data, zlib itself inflates the assembly back to the input.
#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "storage/deflate_parts.hpp"

namespace vimg {
namespace {

// Bytes of three kinds: random (incompressible), runs (what Up-filtered pixels look like), text.
std::vector<std::uint8_t> sample(std::mt19937& rng, std::size_t size, int kind) {
  std::vector<std::uint8_t> bytes(size);
  std::uniform_int_distribution<int> byte(0, 255), run(1, 300);
  const std::string words = "<dot id=\"p12\" x=\"103.25\" y=\"7.5\" radius=\"1.25\"/>\n";
  for (std::size_t i = 0; i < size;) {
    if (kind == 0) {
      bytes[i++] = static_cast<std::uint8_t>(byte(rng));
    } else if (kind == 1) {
      const auto value = static_cast<std::uint8_t>(byte(rng) < 200 ? 0 : byte(rng));
      for (int n = run(rng); n > 0 && i < size; --n) bytes[i++] = value;
    } else {
      bytes[i] = static_cast<std::uint8_t>(words[i % words.size()] + (byte(rng) < 8 ? 1 : 0));
      ++i;
    }
  }
  return bytes;
}

std::string assemble(const std::vector<std::uint8_t>& raw, const std::vector<std::size_t>& cuts,
                     const DeflateSettings& settings) {
  const auto header = zlib_header(settings.level);
  std::string stream(header.begin(), header.end());
  std::uint32_t adler = 1;
  std::size_t begin = 0;
  for (std::size_t i = 0; i <= cuts.size(); ++i) {
    const std::size_t end = i < cuts.size() ? cuts[i] : raw.size();
    const DeflatedPart part = deflate_part({raw.data() + begin, end - begin}, settings, i == cuts.size(), stream);
    EXPECT_EQ(part.raw_bytes, end - begin);
    adler = combine_adler(adler, part.adler, part.raw_bytes);
    begin = end;
  }
  const auto trailer = zlib_trailer(adler);
  stream.append(trailer.begin(), trailer.end());
  return stream;
}

std::vector<std::uint8_t> inflate_all(const std::string& stream, std::size_t expected_size, int& code) {
  std::vector<std::uint8_t> out(expected_size + 16);
  uLongf size = out.size();
  code = uncompress(out.data(), &size, reinterpret_cast<const Bytef*>(stream.data()), stream.size());
  out.resize(size);
  return out;
}

TEST(DeflateParts, AnyCutsAndSettingsInflateToTheInput) {
  std::mt19937 rng(7);
  const DeflateSettings settings[] = {{1, Z_HUFFMAN_ONLY, 9}, {1, Z_RLE, 8},        {1, Z_DEFAULT_STRATEGY, 8},
                                      {6, Z_DEFAULT_STRATEGY, 9}, {9, Z_FILTERED, 1}, {0, Z_DEFAULT_STRATEGY, 8}};
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t size = std::uniform_int_distribution<std::size_t>(0, 300000)(rng);
    const auto raw = sample(rng, size, trial % 3);
    // Random cut points, repeats allowed (empty parts), in order.
    std::vector<std::size_t> cuts(std::uniform_int_distribution<std::size_t>(0, 9)(rng));
    for (std::size_t& cut : cuts) cut = std::uniform_int_distribution<std::size_t>(0, size)(rng);
    std::sort(cuts.begin(), cuts.end());
    const DeflateSettings& s = settings[trial % 6];
    const std::string stream = assemble(raw, cuts, s);
    int code = 0;
    const auto back = inflate_all(stream, size, code);
    ASSERT_EQ(code, Z_OK) << "trial " << trial << ", " << cuts.size() + 1 << " parts of " << size << " bytes";
    EXPECT_TRUE(back == raw) << "trial " << trial;
  }
}

TEST(DeflateParts, ADamagedChecksumIsCaughtByZlib) {
  std::mt19937 rng(3);
  const auto raw = sample(rng, 50000, 2);
  std::string stream = assemble(raw, {10000, 30000}, {1, Z_DEFAULT_STRATEGY});
  stream.back() = static_cast<char>(stream.back() ^ 1);
  int code = 0;
  inflate_all(stream, raw.size(), code);
  EXPECT_EQ(code, Z_DATA_ERROR);
}

TEST(DeflateParts, CombinedAdlerIsTheAdlerOfTheWhole) {
  std::mt19937 rng(11);
  const auto raw = sample(rng, 100000, 0);
  for (const std::size_t cut : {std::size_t{0}, std::size_t{1}, std::size_t{65521}, std::size_t{99999}, raw.size()}) {
    const auto a = static_cast<std::uint32_t>(adler32_z(1, raw.data(), cut));
    const auto b = static_cast<std::uint32_t>(adler32_z(1, raw.data() + cut, raw.size() - cut));
    EXPECT_EQ(combine_adler(a, b, raw.size() - cut), static_cast<std::uint32_t>(adler32_z(1, raw.data(), raw.size())))
        << "cut at " << cut;
  }
}

TEST(DeflateParts, HeaderIsAValidZlibHeaderForEveryLevel) {
  for (int level = 0; level <= 9; ++level) {
    const auto h = zlib_header(level);
    EXPECT_EQ(h[0], 0x78) << level;                     // deflate, 32 KiB window
    EXPECT_EQ((h[0] * 256 + h[1]) % 31, 0) << level;    // RFC 1950 check bits
    EXPECT_EQ(h[1] & 0x20, 0) << level;                 // no preset dictionary
  }
  EXPECT_EQ(zlib_header(1)[1], 0x01);  // what zlib writes at level 1
  EXPECT_EQ(zlib_header(6)[1], 0x9c);  // and at its default level
  EXPECT_EQ(zlib_header(9)[1], 0xda);
}

}  // namespace
}  // namespace vimg
