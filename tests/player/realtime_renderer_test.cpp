// The real-time thread: the deadline schedule, cross-fade, and the lock-free handoffs (run under TSan
// in CI).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <span>
#include <thread>
#include <vector>

#include "fake_shader.hpp"
#include "player/drive_sinks.hpp"
#include "player/realtime_renderer.hpp"

namespace vimg {
namespace {

using namespace std::chrono_literals;

using test::constant_scene;

TouchEvent touch(TouchPhase phase, double x_mm, int finger = 0) {
  TouchEvent e;
  e.time_s = monotonic_s();
  e.finger = finger;
  e.phase = phase;
  e.x_mm = x_mm;
  e.y_mm = 10.0;
  return e;
}

// Keeps every block's time and size (reserved ahead) and publishes how many it has seen, so that a
// test waits on the stream's state instead of sleeping.
class BlockRecorder final : public DriveSink {
 public:
  explicit BlockRecorder(std::size_t capacity) : times_s(capacity), sizes(capacity), zero(capacity, true) {}
  void open(double) override {}
  void write(std::span<const float> drive, double block_start_time_s) override {
    const std::size_t k = count_.load(std::memory_order_relaxed);
    if (k == times_s.size()) return;
    times_s[k] = block_start_time_s;
    sizes[k] = drive.size();
    for (const float v : drive) zero[k] = zero[k] && v == 0.0f;
    count_.store(k + 1, std::memory_order_release);
  }
  void close() override { closed = true; }
  std::size_t count() const { return count_.load(std::memory_order_acquire); }
  std::vector<double> times_s;
  std::vector<std::size_t> sizes;
  std::vector<bool> zero;
  bool closed = false;

 private:
  std::atomic<std::size_t> count_{0};
};

// Waits (polling, never a fixed sleep) until `done()`; gives up after 30 s.
template <class Done>
void wait_until(Done done) {
  const auto give_up = std::chrono::steady_clock::now() + 30s;
  while (!done() && std::chrono::steady_clock::now() < give_up) std::this_thread::sleep_for(1ms);
}

// The deadline schedule, whatever the machine's speed: block k starts at start + k * block / rate,
// every block of the same size, and the schedule jumps forward only where the loop skipped (the
// rate achieved is the machine's: bench/player_bench.cpp, BM_RealtimeLoopJitter, measures it).
TEST(RealtimeRenderer, BlocksFollowTheDeadlineSchedule) {
  BlockRecorder sink(20000);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  RealtimeRenderer r(sink, o);
  ASSERT_FALSE(r.start());
  wait_until([&] { return sink.count() >= 1000; });
  const LoopStats s = r.stats();
  r.stop();
  const std::size_t n = sink.count();
  ASSERT_GE(n, 1000u);
  EXPECT_EQ(s.block_samples, 8u);  // 1 ms
  EXPECT_FALSE(s.paced_by_sink);
  const double block_s = 8.0 / 8000.0;
  std::uint64_t jumps = 0;
  for (std::size_t k = 0; k < n; ++k) {
    ASSERT_EQ(sink.sizes[k], 8u) << k;
    ASSERT_TRUE(sink.zero[k]) << k;  // no scene, no touch: silence
    if (k == 0) continue;
    const double blocks = (sink.times_s[k] - sink.times_s[0]) / block_s;
    ASSERT_NEAR(blocks, std::round(blocks), 1e-6) << k;  // on the schedule
    const double step = (sink.times_s[k] - sink.times_s[k - 1]) / block_s;
    ASSERT_GE(step, 1.0 - 1e-6) << k;
    if (step > 1.5) ++jumps;
  }
  EXPECT_EQ(jumps, r.stats().skips);
  EXPECT_GT(s.measured_rate_hz, 0.0);
  EXPECT_LE(s.jitter_p50_s, s.jitter_p99_s);
  EXPECT_LE(s.jitter_p99_s, s.jitter_max_s + 10e-6);
  EXPECT_GT(s.render_max_s, 0.0);
  EXPECT_LE(s.render_mean_s, s.render_max_s);
  EXPECT_TRUE(sink.closed);
}

// A sink that needs blocks of at least `min` samples.
class BlockySink final : public DriveSink {
 public:
  explicit BlockySink(std::size_t min) : min_(min) {}
  void open(double) override {}
  void write(std::span<const float> drive, double) override { smallest = std::min(smallest, drive.size()); }
  void close() override {}
  std::size_t min_block_samples() const override { return min_; }
  std::size_t smallest = 1u << 30;

 private:
  std::size_t min_;
};

TEST(RealtimeRenderer, BlocksAreOneMillisecondUnlessTheSinkNeedsMore) {
  auto block_at = [](double rate_hz, std::size_t requested, std::size_t sink_min) {
    BlockySink sink(sink_min);
    RealtimeOptions o;
    o.sample_rate_hz = rate_hz;
    o.block_samples = requested;
    RealtimeRenderer r(sink, o);
    EXPECT_FALSE(r.start());
    std::this_thread::sleep_for(30ms);
    r.stop();
    EXPECT_EQ(sink.smallest, r.block_samples());
    EXPECT_EQ(r.stats().block_samples, r.block_samples());
    return r.block_samples();
  };
  EXPECT_EQ(block_at(8000.0, 0, 1), 8u);      // 1 ms
  EXPECT_EQ(block_at(48000.0, 0, 1), 48u);    // 1 ms
  EXPECT_EQ(block_at(1000.0, 0, 1), 1u);      // 1 ms
  EXPECT_EQ(block_at(8000.0, 0, 32), 32u);    // the sink's minimum
  EXPECT_EQ(block_at(8000.0, 64, 1), 64u);    // as asked
  EXPECT_EQ(block_at(8000.0, 1000, 1), 160u); // at most 1/50 s
  EXPECT_EQ(block_at(8000.0, 1000, 400), 400u);  // unless the sink needs more
}

TEST(RealtimeRenderer, ReportsThePriorityItAskedForAndGot) {
  MemorySink sink(8000);
  RealtimeOptions o;
  o.realtime_priority = 0;
  {
    RealtimeRenderer r(sink, o);
    ASSERT_FALSE(r.start());
    std::this_thread::sleep_for(20ms);
    const LoopStats s = r.stats();
    r.stop();
    EXPECT_EQ(s.priority.requested, 0);
    EXPECT_FALSE(s.realtime_priority);
    EXPECT_EQ(describe(s.priority), "normal priority");
  }
  o.realtime_priority = 150;  // clamped to 99; granted only with CAP_SYS_NICE or an rtprio limit
  RealtimeRenderer r(sink, o);
  ASSERT_FALSE(r.start());
  std::this_thread::sleep_for(20ms);
  const LoopStats s = r.stats();
  r.stop();
  EXPECT_EQ(s.priority.requested, 99);
  EXPECT_EQ(s.realtime_priority, s.priority.granted);
  EXPECT_EQ(s.priority.granted, s.priority.error_number == 0);
  EXPECT_NE(describe(s.priority).find("SCHED_FIFO 99"), std::string::npos) << describe(s.priority);
}

TEST(RealtimeRenderer, RejectsRatesOutsideOneTo48kHz) {
  MemorySink sink;
  RealtimeOptions o;
  o.sample_rate_hz = 96000.0;
  RealtimeRenderer r(sink, o);
  EXPECT_TRUE(r.start().has_value());
}

TEST(RealtimeRenderer, SceneChangeCrossFadesWithoutAStep) {
  MemorySink sink(8000 * 10);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  o.crossfade_s = 0.02;
  RealtimeRenderer r(sink, o);
  r.set_scene(constant_scene(0.4));
  ASSERT_FALSE(r.start());
  std::this_thread::sleep_for(50ms);
  ASSERT_TRUE(r.push_event(touch(TouchPhase::down, 10.0)));
  std::this_thread::sleep_for(150ms);
  r.set_scene(constant_scene(0.1));
  std::this_thread::sleep_for(150ms);
  r.stop();
  const auto& d = sink.samples();
  // The touch lands on a steady scene: one jump there (the shader's own onset), none after it.
  std::size_t onset = 0;
  while (onset < d.size() && d[onset] == 0.0f) ++onset;
  ASSERT_LT(onset + 1, d.size());
  const double fade_samples = 0.02 * 8000.0;
  const auto stop_ramp = static_cast<std::size_t>(o.stop_ramp_s * 8000.0);
  ASSERT_GT(d.size(), onset + stop_ramp + 1);
  const std::size_t ramp_start = d.size() - stop_ramp;  // stop() ramps the output out (tested below)
  double max_step = 0.0;
  bool saw_plateau = false;
  for (std::size_t i = onset + 1; i < ramp_start; ++i) {
    max_step = std::max(max_step, static_cast<double>(std::fabs(d[i] - d[i - 1])));
    if (std::fabs(d[i] - 0.4f) < 1e-6f) saw_plateau = true;
  }
  EXPECT_TRUE(saw_plateau);
  EXPECT_LE(max_step, 0.3 / fade_samples * 1.01 + 1e-6);
  EXPECT_NEAR(d[ramp_start - 1], 0.1f, 1e-6f);
}

// Stopping while a finger plays does not cut the drive with a step: the last stop_ramp_s ramp it
// linearly to exactly 0, whatever the block size.
TEST(RealtimeRenderer, StopRampsTheOutputToZeroInsteadOfCuttingIt) {
  for (const std::size_t block : {std::size_t{8}, std::size_t{64}}) {
    MemorySink sink(8000 * 10);
    RealtimeOptions o;
    o.sample_rate_hz = 8000.0;
    o.block_samples = block;
    RealtimeRenderer r(sink, o);
    r.set_scene(constant_scene(0.5));
    ASSERT_FALSE(r.start());
    std::this_thread::sleep_for(30ms);
    ASSERT_TRUE(r.push_event(touch(TouchPhase::down, 10.0)));
    std::this_thread::sleep_for(150ms);
    r.stop();
    const auto& d = sink.samples();
    const auto ramp = static_cast<std::size_t>(std::lround(o.stop_ramp_s * 8000.0));  // 40 samples
    std::size_t last_full = d.size();
    while (last_full > 0 && std::fabs(d[last_full - 1] - 0.5f) > 1e-6f) --last_full;
    ASSERT_GT(last_full, 0u) << "block " << block << ": the finger never played";
    // From the last full-level sample: 0.5 (R-1)/R, ..., 0.5/R, 0 (then zeros to the block's end).
    ASSERT_GE(d.size() - last_full, ramp) << block;
    for (std::size_t j = 0; j < ramp; ++j) {
      const double expected = 0.5 * (1.0 - static_cast<double>(j + 1) / static_cast<double>(ramp));
      ASSERT_NEAR(d[last_full + j], expected, 1e-6) << "block " << block << ", ramp sample " << j;
    }
    for (std::size_t i = last_full + ramp; i < d.size(); ++i) ASSERT_EQ(d[i], 0.0f) << block;
    EXPECT_EQ(d.back(), 0.0f);
  }
}

TEST(RealtimeRenderer, EventsAndScenesFromOtherThreadsWhilePlaying) {
  MemorySink sink(8000 * 10);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  o.crossfade_s = 0.005;
  RealtimeRenderer r(sink, o);
  r.set_scene(constant_scene(0.2));
  ASSERT_FALSE(r.start());
  std::atomic<bool> done{false};
  std::thread producer([&] {
    double x = 1.0;
    r.push_event(touch(TouchPhase::down, x, 1));
    while (!done.load()) {
      x += 0.01;
      r.push_event(touch(TouchPhase::move, x, 1));
      std::this_thread::sleep_for(1ms);
    }
    r.push_event(touch(TouchPhase::up, x, 1));
  });
  std::uint64_t last = 0;
  for (int i = 0; i < 40; ++i) {
    last = r.set_scene(constant_scene(0.1 + 0.01 * (i % 5)));
    std::this_thread::sleep_for(10ms);
  }
  done.store(true);
  producer.join();
  std::this_thread::sleep_for(50ms);
  const LoopStats s = r.stats();
  r.stop();
  EXPECT_EQ(last, 41u);
  EXPECT_EQ(s.scene_generation, last);
  EXPECT_GT(s.blocks, 20u);
  double peak = 0.0;
  for (float v : sink.samples()) {
    ASSERT_LE(std::fabs(v), 1.0f);
    peak = std::max(peak, static_cast<double>(std::fabs(v)));
  }
  EXPECT_GT(peak, 0.09);  // the touches were rendered
  EXPECT_EQ(sink.samples().back(), 0.0f);  // lifted: silence
}

// Scene edits while playing: every edit is a distinct constant drive under a resting finger. Edits
// come faster than one cross-fade (20 ms), so some are replaced before the render thread takes
// them; the last one must always arrive and play once its cross-fade has settled.
void play_edits(double edits_per_s) {
  MemorySink sink(8000 * 10);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  o.crossfade_s = 0.02;
  RealtimeRenderer r(sink, o);
  EXPECT_EQ(r.set_scene(constant_scene(0.05)), 1u);
  ASSERT_FALSE(r.start());
  ASSERT_TRUE(r.push_event(touch(TouchPhase::down, 10.0)));
  std::this_thread::sleep_for(30ms);
  constexpr int kEdits = 120;
  auto drive_of = [](int i) { return 0.1 + 0.003 * i; };  // 0.1 .. 0.457: below the limiter's knee
  const auto interval = std::chrono::duration<double>(edits_per_s > 0.0 ? 1.0 / edits_per_s : 0.0);
  auto next = std::chrono::steady_clock::now();
  std::uint64_t last = 0;
  for (int i = 0; i < kEdits; ++i) {
    last = r.set_scene(constant_scene(drive_of(i)));
    next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(interval);
    std::this_thread::sleep_until(next);
  }
  std::this_thread::sleep_for(120ms);  // the last cross-fade (20 ms) has long settled
  const LoopStats s = r.stats();
  r.stop();
  EXPECT_EQ(last, 1u + kEdits);
  EXPECT_EQ(s.scene_generation, last) << "the renderer took the last scene";
  // What played last, before stop() ramped it out (at most one ramp and one block from the end).
  const auto tail = static_cast<std::size_t>(std::lround(o.stop_ramp_s * 8000.0)) + r.block_samples();
  ASSERT_GT(sink.samples().size(), tail);
  EXPECT_FLOAT_EQ(sink.samples()[sink.samples().size() - 1 - tail], static_cast<float>(drive_of(kEdits - 1)));
}

TEST(RealtimeRenderer, TheLastOfABurstOfEditsAlwaysArrives) { play_edits(0.0); }

TEST(RealtimeRenderer, TheLastOfSixtyEditsPerSecondAlwaysArrives) { play_edits(60.0); }

}  // namespace
}  // namespace vimg
