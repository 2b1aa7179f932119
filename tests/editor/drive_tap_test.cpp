#include "editor/core/drive_tap.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "../player/fake_device_sink.hpp"
#include "../player/fake_shader.hpp"
#include "player/drive_sinks.hpp"
#include "player/realtime_renderer.hpp"
#include "player/touch_event.hpp"

namespace vimg::editor {
namespace {

constexpr double kRate = 8000.0;

TEST(DriveTap, ForwardsEveryBlockUnchanged) {
  MemorySink memory;
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> a(64, 0.25f), b(64, -0.5f);
  tap.write(a, 10.0);
  tap.write(b, 10.008);
  tap.close();
  ASSERT_EQ(memory.samples().size(), 128u);
  EXPECT_FLOAT_EQ(memory.samples()[0], 0.25f);
  EXPECT_FLOAT_EQ(memory.samples()[127], -0.5f);
  EXPECT_TRUE(memory.closed());
  std::vector<float> recent;
  tap.copy_recent(recent, 100);
  ASSERT_EQ(recent.size(), 100u);
  EXPECT_FLOAT_EQ(recent.front(), 0.25f);
  EXPECT_FLOAT_EQ(recent.back(), -0.5f);
}

TEST(DriveTap, MapsRendererTimeToOutputTimeAcrossSkippedBlocks) {
  MemorySink memory;
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> block(64, 0.0f);  // 8 ms
  tap.write(block, 10.000);
  tap.write(block, 10.008);
  tap.write(block, 10.040);  // the renderer fell behind and skipped 24 ms
  EXPECT_NEAR(tap.first_block_time_s(), 10.0, 1e-12);
  EXPECT_NEAR(tap.output_time_s(10.004), 0.004, 1e-9);
  EXPECT_NEAR(tap.output_time_s(10.012), 0.012, 1e-9);
  EXPECT_NEAR(tap.output_time_s(10.030), 0.016, 1e-9) << "inside the gap: its end";
  EXPECT_NEAR(tap.output_time_s(10.041), 0.017, 1e-9);
}

TEST(DriveTap, RecordsOneLatencyPerDriveOnset) {
  MemorySink memory;
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> silent(64, 0.0f), driven(64, 0.3f);
  tap.note_event(monotonic_s());
  tap.write(silent, 0.0);
  tap.write(driven, 0.008);
  tap.write(driven, 0.016);
  tap.write(silent, 0.024);
  tap.write(driven, 0.032);
  const std::vector<double> latencies = tap.latencies_s();
  ASSERT_EQ(latencies.size(), 2u);
  for (double l : latencies) EXPECT_GE(l, 0.0);
}

TEST(DriveTap, IsTransparentToTheRendererAboutPacingAndBlockSize) {
  MemorySink memory;
  DriveTap file_tap(memory);
  EXPECT_FALSE(file_tap.paces_stream());
  EXPECT_EQ(file_tap.min_block_samples(), 1u);
  test::FakeDeviceSink device(1.0, 64);
  DriveTap device_tap(device);
  EXPECT_TRUE(device_tap.paces_stream()) << "the renderer must let the device's clock pace it";
}

TEST(DriveTap, MapsRendererTimeToOutputTimeOverManyOneMillisecondBlocks) {
  MemorySink memory(8 * 20000);
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> block(8, 0.0f);  // 1 ms
  const double start = 12345.678;
  for (std::uint64_t k = 0; k < 20000; ++k) tap.write(block, start + static_cast<double>(k * 8) / kRate);
  for (double t : {0.0, 0.0005, 1.0, 7.25, 19.999}) {
    EXPECT_NEAR(tap.output_time_s(start + t), t, 1e-9) << t;
  }
}

// With an output that paces the stream (its clock 1 % slow, 32 ms queued, as a sound card's ring)
// and 1 ms blocks: the output time the tap gives for an event's renderer time is where that
// event's drive starts in the output. (The event's CLOCK_MONOTONIC time would be about the queue
// length off; the bounds leave room for the render thread's scheduling on a loaded machine.)
TEST(DriveTap, AnEventMapsToWhereItsDriveStartsWithAPacingOutput) {
  test::FakeDeviceSink device(0.99, 256);
  DriveTap tap(device);
  RealtimeOptions o;
  o.sample_rate_hz = kRate;
  o.crossfade_s = 0.002;
  RealtimeRenderer renderer(tap, o);
  std::vector<ScenePrimitive> prims;
  const Bounds2M box{0.0, 0.0, 1.0, 1.0};
  prims.push_back({std::make_unique<test::FakeShader>(box, 0.3), box, "all"});
  renderer.set_scene(std::make_shared<const Scene>(std::move(prims), Vec3{0, 0, 1}, 1.0));
  ASSERT_FALSE(renderer.start());
  EXPECT_EQ(renderer.block_samples(), 8u);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  TouchEvent down;
  down.time_s = monotonic_s();
  down.phase = TouchPhase::down;
  down.x_mm = 10.0;
  down.y_mm = 10.0;
  const double down_on_renderer_clock_s = renderer.renderer_time_s(down.time_s);
  ASSERT_TRUE(renderer.push_event(down));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  renderer.stop();
  EXPECT_TRUE(renderer.stats().paced_by_sink);
  std::size_t onset = 0;
  while (onset < device.samples.size() && device.samples[onset] == 0.0f) ++onset;
  ASSERT_LT(onset, device.samples.size());
  const double onset_s = static_cast<double>(onset) / kRate;
  const double mapped_s = tap.output_time_s(down_on_renderer_clock_s);
  EXPECT_GT(onset_s - mapped_s, -0.010);
  EXPECT_LT(onset_s - mapped_s, 0.010);
  EXPECT_GT(renderer.renderer_time_s(down.time_s) - down.time_s, 0.015) << "the queue puts the stream ahead";
}

}  // namespace
}  // namespace vimg::editor
