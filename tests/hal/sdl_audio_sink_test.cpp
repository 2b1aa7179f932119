#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <vector>

#include <SDL.h>
#include <unistd.h>

#include "hal/sdl_audio_sink.hpp"

namespace vimg {
namespace {

std::vector<float> read_floats(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<float> samples;
  float value = 0.0f;
  while (in.read(reinterpret_cast<char*>(&value), sizeof value)) samples.push_back(value);
  return samples;
}

class SdlAudioSinkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = std::filesystem::temp_directory_path() / ("vimg_sdl_disk_audio_" + std::to_string(::getpid()) + ".raw");
    std::filesystem::remove(file_);
    setenv("SDL_AUDIODRIVER", "disk", 1);
    setenv("SDL_DISKAUDIOFILE", file_.c_str(), 1);
  }
  void TearDown() override {
    std::filesystem::remove(file_);
    unsetenv("SDL_AUDIODRIVER");
    unsetenv("SDL_DISKAUDIOFILE");
  }
  std::filesystem::path file_;
};

TEST_F(SdlAudioSinkTest, WritesTheDriveSamplesToTheDevice) {
  std::vector<float> drive(2000);
  for (std::size_t i = 0; i < drive.size(); ++i) {
    drive[i] = static_cast<float>(0.7 * std::sin(2.0 * std::numbers::pi * 175.0 * static_cast<double>(i + 1) / 8000.0));
  }
  {
    SdlAudioOptions options;
    options.device_buffer_frames = 128;
    SdlAudioSink sink(options);
    sink.open(8000.0);
    EXPECT_EQ(sink.obtained_buffer_frames(), 128);
    EXPECT_NEAR(sink.buffer_latency_s(), (128.0 + 4 * 128.0) / 8000.0, 1e-9);
    for (std::size_t start = 0; start < drive.size(); start += 100) {
      sink.write(std::span<const float>(drive).subspan(start, 100), static_cast<double>(start) / 8000.0);
    }
    sink.close();
    EXPECT_EQ(sink.underruns(), 0u);
  }
  const auto written = read_floats(file_);
  // Silence may come first (the device starts before the first block); then every sample, in order.
  std::size_t first = 0;
  while (first < written.size() && written[first] == 0.0f) ++first;
  ASSERT_GE(written.size(), first + drive.size());
  for (std::size_t i = 0; i < drive.size(); ++i) {
    ASSERT_FLOAT_EQ(written[first + i], drive[i]) << i;
  }
  for (std::size_t i = first + drive.size(); i < written.size(); ++i) {
    ASSERT_EQ(written[i], 0.0f);  // ends at rest
  }
}

TEST_F(SdlAudioSinkTest, DefaultBuffersAreAboutEightMilliseconds) {
  for (const double rate : {8000.0, 48000.0}) {
    SdlAudioSink sink;
    sink.open(rate);
    const double device_s = sink.obtained_buffer_frames() / rate;
    EXPECT_GE(device_s, 0.004) << rate;
    EXPECT_LE(device_s, 0.016) << rate;
    EXPECT_NEAR(sink.buffer_latency_s(), 5.0 * device_s, 1e-9);
    sink.close();
  }
}

TEST_F(SdlAudioSinkTest, UnknownDeviceNameIsAClearError) {
  SdlAudioOptions options;
  options.device_name = "no such speaker";
  SdlAudioSink sink(options);
  try {
    sink.open(8000.0);
    FAIL();
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no such speaker"), std::string::npos) << message;
    EXPECT_NE(message.find("disk"), std::string::npos) << message;
  }
}

TEST_F(SdlAudioSinkTest, LateBlocksCountAsUnderruns) {
  SdlAudioOptions options;
  options.device_buffer_frames = 64;
  SdlAudioSink sink(options);
  sink.open(8000.0);
  const std::vector<float> block(64, 0.5f);
  sink.write(block, 0.0);
  SDL_Delay(100);  // the device asks for more than we gave
  EXPECT_GE(sink.underruns(), 1u);
  sink.close();
}

}  // namespace
}  // namespace vimg
