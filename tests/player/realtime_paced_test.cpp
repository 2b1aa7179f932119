// A sink with its own clock paces the stream: the renderer follows it block after block, never
// skips, and every tap reaches the drive, whether the device clock runs slow or fast. The taps
// wait on what the output shows, never on fixed sleeps, and nothing here bounds a delay: how far
// the event mapping lags a drifting device is StreamClock's logic, checked on a simulated clock
// (stream_clock_test.cpp); the latency a machine achieves is bench/player_bench.cpp's.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>
#include <vector>

#include "fake_device_sink.hpp"
#include "fake_shader.hpp"
#include "player/realtime_renderer.hpp"

namespace vimg {
namespace {

using namespace std::chrono_literals;

using test::constant_scene;

TouchEvent touch(TouchPhase phase) {
  TouchEvent e;
  e.time_s = monotonic_s();
  e.phase = phase;
  e.x_mm = 10.0;
  e.y_mm = 10.0;
  return e;
}

// Polls until `done()` (the output's state); false if it never came within 30 s.
template <class Done>
bool wait_until(Done done) {
  const auto give_up = std::chrono::steady_clock::now() + 30s;
  while (!done()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(100us);
  }
  return true;
}

// 20 taps on a device whose clock runs at `speed`: each finger goes down, stays until its drive
// reaches the output, and lifts; the next tap waits until the output is silent again.
void tap_on_drifting_device(double speed) {
  constexpr double kRate = 8000.0;
  constexpr std::size_t kQueue = 64;  // 8 ms
  constexpr int kTaps = 20;
  test::FakeDeviceSink sink(speed, kQueue);
  RealtimeOptions o;
  o.sample_rate_hz = kRate;
  o.crossfade_s = 0.002;
  // Staleness is the tracker's (live_tracker_test.cpp): a loaded machine must not make a tap stale.
  o.tracker.stale_after_s = 10.0;
  RealtimeRenderer r(sink, o);
  r.set_scene(constant_scene(0.3));
  ASSERT_FALSE(r.start());
  ASSERT_TRUE(wait_until([&] { return sink.blocks_written() >= 10; }));
  std::vector<double> downs_s;
  for (int tap = 0; tap < kTaps; ++tap) {
    const TouchEvent down = touch(TouchPhase::down);
    downs_s.push_back(down.time_s);
    ASSERT_TRUE(r.push_event(down));
    ASSERT_TRUE(wait_until([&] { return sink.last_block_driven(); })) << "tap " << tap << " produced no drive";
    ASSERT_TRUE(r.push_event(touch(TouchPhase::up)));
    ASSERT_TRUE(wait_until([&] { return !sink.last_block_driven(); })) << "tap " << tap << " never ended";
  }
  r.stop();
  const LoopStats s = r.stats();

  // One clock: block after block, no gap and no skip.
  EXPECT_TRUE(s.paced_by_sink);
  ASSERT_GT(sink.blocks.size(), 10u);
  for (std::size_t k = 1; k < sink.blocks.size(); ++k) {
    const auto& a = sink.blocks[k - 1];
    ASSERT_NEAR(sink.blocks[k].time_s, a.time_s + static_cast<double>(a.size) / kRate, 1e-9) << k;
  }
  EXPECT_EQ(s.skips, 0u);
  EXPECT_EQ(s.dropped_events, 0u);

  // Each tap's drive starts once, in a block written after its event.
  std::size_t onsets = 0;
  for (std::size_t k = 0; k < sink.blocks.size(); ++k) {
    if (!sink.blocks[k].nonzero || (k > 0 && sink.blocks[k - 1].nonzero)) continue;
    ASSERT_LT(onsets, downs_s.size()) << "more drive onsets than taps";
    EXPECT_GE(sink.blocks[k].written_at_s, downs_s[onsets]) << "tap " << onsets << " drove before its event";
    ++onsets;
  }
  EXPECT_EQ(onsets, downs_s.size());
}

TEST(RealtimePaced, ADeviceClockOnePercentSlowPacesTheRendererAndTapsStillDrive) { tap_on_drifting_device(0.99); }

TEST(RealtimePaced, ADeviceClockOnePercentFastPacesTheRendererAndTapsStillDrive) { tap_on_drifting_device(1.01); }

}  // namespace
}  // namespace vimg
