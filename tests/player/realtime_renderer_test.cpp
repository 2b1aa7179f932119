// The real-time thread: rate, cross-fade, and the lock-free handoffs (run under TSan in CI).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "fake_shader.hpp"
#include "player/drive_sinks.hpp"
#include "player/realtime_renderer.hpp"

namespace vimg {
namespace {

using namespace std::chrono_literals;

std::shared_ptr<const Scene> constant_scene(double drive) {
  std::vector<ScenePrimitive> prims;
  const Bounds2M box{0.0, 0.0, 1.0, 1.0};
  prims.push_back({std::make_unique<test::FakeShader>(box, drive), box, "all"});
  return std::make_shared<const Scene>(std::move(prims), Vec3{0, 0, 1}, 1.0);
}

TouchEvent touch(TouchPhase phase, double x_mm, int finger = 0) {
  TouchEvent e;
  e.time_s = monotonic_s();
  e.finger = finger;
  e.phase = phase;
  e.x_mm = x_mm;
  e.y_mm = 10.0;
  return e;
}

TEST(RealtimeRenderer, RunsAtTheRequestedRate) {
  MemorySink sink(8000 * 10);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  RealtimeRenderer r(sink, o);
  ASSERT_FALSE(r.start());
  const auto t0 = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(1200ms);
  const LoopStats s = r.stats();
  r.stop();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_NEAR(s.measured_rate_hz, 8000.0, 8000.0 * 0.15);
  EXPECT_NEAR(static_cast<double>(sink.samples().size()), elapsed * 8000.0, elapsed * 8000.0 * 0.15);
  EXPECT_EQ(sink.samples().size() % r.block_samples(), 0u);
  EXPECT_LE(s.jitter_p50_s, s.jitter_p99_s);
  EXPECT_LE(s.jitter_p99_s, s.jitter_max_s + 10e-6);
  EXPECT_TRUE(sink.closed());
  for (float v : sink.samples()) ASSERT_EQ(v, 0.0f);  // no scene, no touch: silence
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
  ASSERT_TRUE(r.set_scene(constant_scene(0.4)));
  ASSERT_FALSE(r.start());
  std::this_thread::sleep_for(50ms);
  ASSERT_TRUE(r.push_event(touch(TouchPhase::down, 10.0)));
  std::this_thread::sleep_for(150ms);
  ASSERT_TRUE(r.set_scene(constant_scene(0.1)));
  std::this_thread::sleep_for(150ms);
  r.stop();
  const auto& d = sink.samples();
  // The touch lands on a steady scene: one jump there (the shader's own onset), none after it.
  std::size_t onset = 0;
  while (onset < d.size() && d[onset] == 0.0f) ++onset;
  ASSERT_LT(onset + 1, d.size());
  const double fade_samples = 0.02 * 8000.0;
  double max_step = 0.0;
  bool saw_plateau = false;
  for (std::size_t i = onset + 1; i < d.size(); ++i) {
    max_step = std::max(max_step, static_cast<double>(std::fabs(d[i] - d[i - 1])));
    if (std::fabs(d[i] - 0.4f) < 1e-6f) saw_plateau = true;
  }
  EXPECT_TRUE(saw_plateau);
  EXPECT_LE(max_step, 0.3 / fade_samples * 1.01 + 1e-6);
  EXPECT_NEAR(d.back(), 0.1f, 1e-6f);
}

TEST(RealtimeRenderer, EventsAndScenesFromOtherThreadsWhilePlaying) {
  MemorySink sink(8000 * 10);
  RealtimeOptions o;
  o.sample_rate_hz = 8000.0;
  o.crossfade_s = 0.005;
  RealtimeRenderer r(sink, o);
  ASSERT_TRUE(r.set_scene(constant_scene(0.2)));
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
  int accepted = 0;
  for (int i = 0; i < 40; ++i) {
    if (r.set_scene(constant_scene(0.1 + 0.01 * (i % 5)))) ++accepted;
    std::this_thread::sleep_for(10ms);
  }
  done.store(true);
  producer.join();
  std::this_thread::sleep_for(50ms);
  const LoopStats s = r.stats();
  r.stop();
  EXPECT_GT(accepted, 10);
  EXPECT_GT(s.blocks, 20u);
  double peak = 0.0;
  for (float v : sink.samples()) {
    ASSERT_LE(std::fabs(v), 1.0f);
    peak = std::max(peak, static_cast<double>(std::fabs(v)));
  }
  EXPECT_GT(peak, 0.09);  // the touches were rendered
  EXPECT_EQ(sink.samples().back(), 0.0f);  // lifted: silence
}

}  // namespace
}  // namespace vimg
