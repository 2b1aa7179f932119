#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <thread>
#include <vector>

#include <SDL.h>
#include <unistd.h>

#include "../player/fake_shader.hpp"
#include "hal/rest_on_exit.hpp"
#include "hal/sdl_audio_sink.hpp"
#include "player/realtime_renderer.hpp"

namespace vimg {
namespace {

std::vector<float> read_floats(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<float> samples;
  float value = 0.0f;
  while (in.read(reinterpret_cast<char*>(&value), sizeof value)) samples.push_back(value);
  return samples;
}

// The non-zero samples, in order: what reached the device, whatever silence an underrun put
// between them (the machine's speed decides underruns; the order and values are the sink's logic).
std::vector<float> nonzero(const std::vector<float>& v) {
  std::vector<float> out;
  for (const float x : v) {
    if (x != 0.0f) out.push_back(x);
  }
  return out;
}

// The runs of silence between the first and the last non-zero sample.
std::size_t silent_runs_inside(const std::vector<float>& v) {
  std::size_t first = 0, last = v.size();
  while (first < v.size() && v[first] == 0.0f) ++first;
  while (last > first && v[last - 1] == 0.0f) --last;
  std::size_t runs = 0;
  for (std::size_t i = first + 1; i < last; ++i) runs += v[i] == 0.0f && v[i - 1] != 0.0f ? 1 : 0;
  return runs;
}

// Polls until `done()`; false if it never came within 30 s.
template <class Done>
bool wait_until(Done done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!done()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
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
  std::uint64_t underruns = 0;
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
    EXPECT_NEAR(sink.buffer_latency_s(), (128.0 + 2 * 128.0) / 8000.0, 1e-9);  // device buffer + a ring of two
    for (std::size_t start = 0; start < drive.size(); start += 100) {
      sink.write(std::span<const float>(drive).subspan(start, 100), static_cast<double>(start) / 8000.0);
    }
    sink.close();
    underruns = sink.underruns();
  }
  const auto written = read_floats(file_);
  // Silence may come first (the device starts before the first block) and wherever the device
  // ran dry (an underrun, counted); then every sample, in order, and the device ends at rest.
  EXPECT_EQ(nonzero(written), nonzero(drive));
  EXPECT_LE(silent_runs_inside(written), underruns);
  ASSERT_FALSE(written.empty());
  EXPECT_EQ(written.back(), 0.0f);
}

TEST_F(SdlAudioSinkTest, DefaultBuffersAreAboutEightMilliseconds) {
  for (const double rate : {8000.0, 48000.0}) {
    SdlAudioSink sink;
    sink.open(rate);
    const double device_s = sink.obtained_buffer_frames() / rate;
    EXPECT_GE(device_s, 0.004) << rate;
    EXPECT_LE(device_s, 0.016) << rate;
    // The device paces the stream and keeps the ring full: device buffer + a ring of two buffers.
    EXPECT_NEAR(sink.buffer_latency_s(), 3.0 * device_s, 1e-9);
    EXPECT_LE(sink.buffer_latency_s(), 0.048) << rate;
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
  // The device asks for more than it was given: it counts an underrun (waited on, not slept for).
  EXPECT_TRUE(wait_until([&] { return sink.underruns() >= 1; }));
  sink.close();
}

// Forwards every block to the SDL sink and keeps what the renderer wrote (reserved ahead).
class Recorder final : public DriveSink {
 public:
  explicit Recorder(DriveSink& out) : out_(out) {
    samples.reserve(8000 * 20);
    block_times_s.reserve(8000 * 20);
    block_sizes.reserve(8000 * 20);
  }
  void open(double rate) override { out_.open(rate); }
  void write(std::span<const float> drive, double block_start_time_s) override {
    samples.insert(samples.end(), drive.begin(), drive.end());
    block_times_s.push_back(block_start_time_s);
    block_sizes.push_back(drive.size());
    out_.write(drive, block_start_time_s);
  }
  void close() override { out_.close(); }
  bool paces_stream() const override { return out_.paces_stream(); }
  std::vector<float> samples;
  std::vector<double> block_times_s;
  std::vector<std::size_t> block_sizes;

 private:
  DriveSink& out_;
};

std::shared_ptr<const Scene> constant_scene(double drive) {
  std::vector<ScenePrimitive> prims;
  const Bounds2M box{0.0, 0.0, 1.0, 1.0};
  prims.push_back({std::make_unique<test::FakeShader>(box, drive), box, "all"});
  return std::make_shared<const Scene>(std::move(prims), Vec3{0, 0, 1}, 1.0);
}

// One clock per stream: the disk driver plays at its own pace, and the renderer follows it. No
// block is skipped, and the file holds exactly the rendered samples.
TEST_F(SdlAudioSinkTest, TheDeviceClockPacesTheRendererWithoutSkips) {
  SdlAudioSink sdl;  // default buffers
  Recorder recorder(sdl);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  {
    RealtimeRenderer r(recorder, o);
    r.set_scene(constant_scene(0.25));
    ASSERT_FALSE(r.start());
    TouchEvent down;
    down.time_s = monotonic_s();
    down.phase = TouchPhase::down;
    down.x_mm = 10.0;
    down.y_mm = 10.0;
    const std::uint64_t at_down = r.stats().blocks;
    ASSERT_TRUE(r.push_event(down));
    // A quarter of a second of the device's own time or more, in blocks it has taken (waited on,
    // not slept for).
    ASSERT_TRUE(wait_until([&] { return r.stats().blocks >= at_down + 2000 / r.block_samples(); }));
    TouchEvent up = down;
    up.time_s = monotonic_s();
    up.phase = TouchPhase::up;
    ASSERT_TRUE(r.push_event(up));
    const std::uint64_t at_up = r.stats().blocks;
    ASSERT_TRUE(wait_until([&] { return r.stats().blocks >= at_up + 20; }));
    const LoopStats s = r.stats();
    r.stop();
    EXPECT_TRUE(s.paced_by_sink);
    EXPECT_EQ(s.skips, 0u);
  }
  EXPECT_TRUE(sdl.paces_stream());
  const double rate = o.sample_rate_hz;
  ASSERT_GT(recorder.block_times_s.size(), 100u);
  std::size_t skips = 0;
  for (std::size_t k = 1; k < recorder.block_times_s.size(); ++k) {
    const double expected = recorder.block_times_s[k - 1] + static_cast<double>(recorder.block_sizes[k - 1]) / rate;
    if (std::fabs(recorder.block_times_s[k] - expected) > 0.5 / rate) ++skips;
  }
  EXPECT_EQ(skips, 0u) << "blocks whose time does not follow the previous block";

  // The file holds exactly the rendered samples, in order, with silence only before the stream,
  // after it, and where the device ran dry (underruns: the machine's speed, not counted against it).
  const auto written = read_floats(file_);
  const std::vector<float> driven = nonzero(recorder.samples);
  ASSERT_GT(driven.size(), 1000u);
  EXPECT_EQ(nonzero(written), driven);
  EXPECT_LE(silent_runs_inside(written), silent_runs_inside(recorder.samples) + sdl.underruns());
}

// A signal asks for rest while the render thread writes: write() plays silence from then on and
// returns, and leaves the device open (closing it blocks and frees; that is the control thread's).
TEST_F(SdlAudioSinkTest, RestRequestSilencesTheOutputWithoutClosingIt) {
  SdlAudioOptions options;
  options.device_buffer_frames = 64;
  SdlAudioSink sink(options);
  sink.open(8000.0);
  const std::vector<float> block(64, 0.5f);
  for (int i = 0; i < 8; ++i) sink.write(block, i * 64 / 8000.0);
  request_rest(SIGTERM);
  for (int i = 8; i < 16; ++i) sink.write(block, i * 64 / 8000.0);
  const bool audio_still_up = SDL_WasInit(SDL_INIT_AUDIO) != 0;
  clear_rest_request();
  EXPECT_TRUE(audio_still_up) << "write() closed the device on the writing thread";
  sink.close();
  EXPECT_EQ(SDL_WasInit(SDL_INIT_AUDIO), 0u);
  const auto written = read_floats(file_);
  std::size_t driven = 0;
  for (float v : written) driven += v != 0.0f ? 1 : 0;
  EXPECT_LE(driven, 8u * 64u) << "nothing written after the rest request may play";
}

}  // namespace
}  // namespace vimg
