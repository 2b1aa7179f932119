#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "player/drive_sinks.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("vimg_player_sinks_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::vector<unsigned char> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t u32(const std::vector<unsigned char>& b, std::size_t at) {
  return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) | (static_cast<std::uint32_t>(b[at + 3]) << 24);
}
std::uint16_t u16(const std::vector<unsigned char>& b, std::size_t at) {
  return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}

TEST(WavSink, WritesMonoFloat32WithFormatTag3) {
  const fs::path out = temp_dir() / "a.wav";
  fs::remove(out);
  WavSink sink(out);
  sink.open(8000.0);
  const std::vector<float> block{0.0f, 0.5f, -0.25f, 1.0f};
  sink.write(block, 0.0);
  sink.write(std::span<const float>(block.data(), 2), 4.0 / 8000.0);
  EXPECT_FALSE(fs::exists(out));  // nothing at the target until complete
  sink.close();
  ASSERT_FALSE(sink.error()) << *sink.error();
  const auto b = read_bytes(out);
  ASSERT_GE(b.size(), 44u);
  EXPECT_EQ(std::memcmp(b.data(), "RIFF", 4), 0);
  EXPECT_EQ(u32(b, 4), b.size() - 8);
  EXPECT_EQ(std::memcmp(b.data() + 8, "WAVE", 4), 0);
  // Walk the chunks.
  std::size_t at = 12;
  bool fmt_seen = false;
  std::vector<float> samples;
  while (at + 8 <= b.size()) {
    const std::string id(reinterpret_cast<const char*>(b.data() + at), 4);
    const std::uint32_t size = u32(b, at + 4);
    if (id == "fmt ") {
      fmt_seen = true;
      EXPECT_EQ(u16(b, at + 8), 3);    // IEEE float
      EXPECT_EQ(u16(b, at + 10), 1);   // mono
      EXPECT_EQ(u32(b, at + 12), 8000u);
      EXPECT_EQ(u32(b, at + 16), 32000u);
      EXPECT_EQ(u16(b, at + 20), 4);
      EXPECT_EQ(u16(b, at + 22), 32);
    } else if (id == "fact") {
      EXPECT_EQ(u32(b, at + 8), 6u);
    } else if (id == "data") {
      ASSERT_EQ(size, 24u);
      for (std::size_t i = 0; i < size / 4; ++i) {
        const std::uint32_t bits = u32(b, at + 8 + 4 * i);
        float f;
        std::memcpy(&f, &bits, 4);
        samples.push_back(f);
      }
    }
    at += 8 + size + (size & 1);
  }
  EXPECT_TRUE(fmt_seen);
  EXPECT_EQ(samples, (std::vector<float>{0.0f, 0.5f, -0.25f, 1.0f, 0.0f, 0.5f}));
}

TEST(CsvSink, WritesTimeAndDriveRows) {
  const fs::path out = temp_dir() / "a.csv";
  CsvSink sink(out);
  sink.open(1000.0);
  const std::vector<float> block{0.0f, 0.125f, -1.0f};
  sink.write(block, 0.5);
  sink.close();
  ASSERT_FALSE(sink.error());
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time_s,drive");
  std::vector<std::pair<double, double>> rows;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    rows.emplace_back(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
  }
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_DOUBLE_EQ(rows[1].first, 0.501);
  EXPECT_DOUBLE_EQ(rows[1].second, 0.125);
  EXPECT_DOUBLE_EQ(rows[2].second, -1.0);
}

TEST(FileSink, AbortLeavesAnExistingTargetUntouched) {
  const fs::path out = temp_dir() / "keep.csv";
  { std::ofstream(out) << "old"; }
  {
    CsvSink sink(out);
    sink.open(100.0);
    const std::vector<float> block{0.5f};
    sink.write(block, 0.0);
    sink.abort();
  }
  std::ifstream in(out);
  std::string s;
  std::getline(in, s);
  EXPECT_EQ(s, "old");
  for (const auto& e : fs::directory_iterator(temp_dir()))
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(FileSink, UnwritableTargetReportsAnErrorNamingIt) {
  WavSink sink("/nonexistent-dir/x.wav");
  sink.open(8000.0);
  const std::vector<float> block{0.5f};
  sink.write(block, 0.0);
  sink.close();
  ASSERT_TRUE(sink.error());
  EXPECT_NE(sink.error()->find("/nonexistent-dir/x.wav"), std::string::npos);
}

TEST(MemorySink, KeepsEverySampleAndTheRate) {
  MemorySink sink(16);
  sink.open(48000.0);
  const std::vector<float> block{0.1f, 0.2f};
  sink.write(block, 1.0);
  sink.write(block, 1.0 + 2.0 / 48000.0);
  sink.close();
  EXPECT_EQ(sink.samples().size(), 4u);
  EXPECT_EQ(sink.sample_rate_hz(), 48000.0);
  EXPECT_EQ(sink.first_block_time_s(), 1.0);
  EXPECT_TRUE(sink.closed());
}

}  // namespace
}  // namespace vimg
