#include "editor/core/drive_tap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "../player/fake_device_sink.hpp"
#include "../player/fake_shader.hpp"
#include "player/drive_sinks.hpp"
#include "player/realtime_renderer.hpp"
#include "player/stream_clock.hpp"
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

// The renderer's clock as a stream paced by an output whose clock runs 1 % slow, 32 ms queued (a
// sound card's ring), 1 ms blocks, on a simulated clock: the render loop of
// RealtimeRenderer::run_paced_by_sink (observe, render, write; write returns when the device has
// room) with the StreamClock it uses. An event stamped at monotonic time e is drawn in the first
// block rendered at or after e, from its mapped time on; the tap maps the event's renderer time
// (taken when the event is pushed) to where that drive starts in the output, within a block,
// whatever the machine's speed.
TEST(DriveTap, AnEventMapsToWhereItsDriveStartsWithAPacingOutputOnASimulatedClock) {
  constexpr std::size_t kBlock = 8;
  constexpr double kQueue = 256.0;
  constexpr double kSpeed = 0.99;
  MemorySink memory(8 * 40000);
  DriveTap tap(memory);
  tap.open(kRate);
  StreamClock clock(kRate);
  const double start_s = 500.0;
  clock.start(start_s);
  struct Rendered {
    double now_s, block_time_s, offset_s;
  };
  std::vector<Rendered> rendered;
  const std::vector<float> block(kBlock, 0.0f);
  double now_s = start_s;
  for (std::uint64_t sample = 0; sample < 8 * 30000; sample += kBlock) {  // 30 s
    clock.observe(sample, now_s);
    rendered.push_back({now_s, clock.sample_time_s(sample), clock.offset_s()});
    tap.write(block, clock.sample_time_s(sample));
    const double written = static_cast<double>(sample + kBlock);
    now_s = std::max(now_s + 2e-6, start_s + (written - kQueue) / (kRate * kSpeed));  // write() returns
  }
  // The stream runs ahead of CLOCK_MONOTONIC by the queue (32 ms), less what the slow device has
  // lost since the start (1 % of the time), and the offset follows it within drift * tau.
  const double drift_lag_s = (1.0 / kSpeed - 1.0) * StreamClock::kDefaultTimeConstant_s;
  for (const std::size_t at : {std::size_t{700}, rendered.size() - 1}) {
    const double raw_s = rendered[at].block_time_s - rendered[at].now_s;
    EXPECT_NEAR(raw_s, kQueue / kRate - (1.0 - kSpeed) * (rendered[at].now_s - start_s), 0.002) << at;
    EXPECT_NEAR(rendered[at].offset_s, raw_s, drift_lag_s + 0.001) << at;
  }
  EXPECT_GT(rendered[700].offset_s, 0.015) << "the queue puts the stream ahead";
  const double lag_bound_s = static_cast<double>(kBlock) / kRate;  // within a block
  double worst_s = 0.0;
  std::size_t k = 1;
  for (double e = start_s + 1.0; e < start_s + 29.0; e += 0.0137) {
    while (rendered[k].now_s < e) ++k;
    const double mapped_s = tap.output_time_s(e + rendered[k - 1].offset_s);  // pushed: the offset published then
    const double drawn_from_s = std::max(rendered[k].block_time_s, e + rendered[k].offset_s);  // rendered
    worst_s = std::max(worst_s, std::fabs(tap.output_time_s(drawn_from_s) - mapped_s));
  }
  EXPECT_LT(worst_s, lag_bound_s);
  std::printf("worst mapping error %.2f ms (bound %.2f ms)\n", worst_s * 1e3, lag_bound_s * 1e3);
}

// The real threads, with the same output: the stream runs ahead and the drive starts no earlier
// than the tap says (a loaded machine only makes it later; how much later is the machine's,
// measured by bench/player_bench.cpp). The renderer's progress is waited on, never slept through.
TEST(DriveTap, AnEventsDriveStartsNoEarlierThanTheTapSaysWithAPacingOutput) {
  test::FakeDeviceSink device(0.99, 256);
  DriveTap tap(device);
  RealtimeOptions o;
  o.sample_rate_hz = kRate;
  o.crossfade_s = 0.002;
  o.tracker.stale_after_s = 10.0;  // a loaded machine must not make the touch stale
  RealtimeRenderer renderer(tap, o);
  std::vector<ScenePrimitive> prims;
  const Bounds2M box{0.0, 0.0, 1.0, 1.0};
  prims.push_back({std::make_unique<test::FakeShader>(box, 0.3), box, "all"});
  renderer.set_scene(std::make_shared<const Scene>(std::move(prims), Vec3{0, 0, 1}, 1.0));
  ASSERT_FALSE(renderer.start());
  EXPECT_EQ(renderer.block_samples(), 8u);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (device.blocks_written() < 300 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  TouchEvent down;
  down.time_s = monotonic_s();
  down.phase = TouchPhase::down;
  down.x_mm = 10.0;
  down.y_mm = 10.0;
  const double down_on_renderer_clock_s = renderer.renderer_time_s(down.time_s);
  ASSERT_TRUE(renderer.push_event(down));
  while (!device.last_block_driven() && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  renderer.stop();
  EXPECT_TRUE(renderer.stats().paced_by_sink);
  std::size_t onset = 0;
  while (onset < device.samples.size() && device.samples[onset] == 0.0f) ++onset;
  ASSERT_LT(onset, device.samples.size());
  const double onset_s = static_cast<double>(onset) / kRate;
  EXPECT_GT(onset_s - tap.output_time_s(down_on_renderer_clock_s), -0.010);
  EXPECT_GT(renderer.renderer_time_s(down.time_s), down.time_s) << "the queue puts the stream ahead";
}

}  // namespace
}  // namespace vimg::editor
