// A sink with its own clock paces the stream: the renderer follows it, never skips, and touch
// events stamped on CLOCK_MONOTONIC still reach the drive promptly when the device clock drifts.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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

// Taps (down, 40 ms, up, 60 ms) for `duration_s` on a device whose clock runs at `speed`. Events
// older than 20 ms on the renderer clock are dropped as stale (the default is 100 ms; a short
// limit shows within seconds what an unanchored stream clock would do over minutes).
void tap_on_drifting_device(double speed) {
  constexpr double kRate = 8000.0;
  constexpr std::size_t kQueue = 64;  // 8 ms
  test::FakeDeviceSink sink(speed, kQueue);
  RealtimeOptions o;
  o.sample_rate_hz = kRate;
  o.crossfade_s = 0.002;
  o.tracker.stale_after_s = 0.02;
  RealtimeRenderer r(sink, o);
  r.set_scene(constant_scene(0.3));
  ASSERT_FALSE(r.start());
  std::this_thread::sleep_for(20ms);
  std::vector<double> downs_s;
  std::vector<double> downs_on_renderer_clock_s;
  const auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < 3s) {
    const TouchEvent down = touch(TouchPhase::down);
    downs_s.push_back(down.time_s);
    downs_on_renderer_clock_s.push_back(r.renderer_time_s(down.time_s));
    ASSERT_TRUE(r.push_event(down));
    std::this_thread::sleep_for(40ms);
    ASSERT_TRUE(r.push_event(touch(TouchPhase::up)));
    std::this_thread::sleep_for(60ms);
  }
  r.stop();
  const LoopStats s = r.stats();

  // One clock: block after block, no gap and no skip.
  ASSERT_GT(sink.blocks.size(), 100u);
  for (std::size_t k = 1; k < sink.blocks.size(); ++k) {
    const auto& a = sink.blocks[k - 1];
    ASSERT_NEAR(sink.blocks[k].time_s, a.time_s + static_cast<double>(a.size) / kRate, 1e-9) << k;
  }
  EXPECT_EQ(s.skips, 0u);
  EXPECT_EQ(s.dropped_events, 0u);

  // Every tap drives the output within a bounded delay of its event: one block plus the time
  // write() waits for the device (a block of device time), plus scheduling slack.
  // On the renderer clock, the event lands where its drive starts: the mapping follows the
  // drifting device (an unanchored stream clock would be 30 ms off after 3 s, 15 ms on average).
  // Single taps also see the render thread's own scheduling delays on a loaded machine.
  std::size_t k = 0;
  std::vector<double> delays_s;
  std::vector<double> onset_minus_event_s;
  for (std::size_t i = 0; i < downs_s.size(); ++i) {
    while (k < sink.blocks.size() && sink.blocks[k].written_at_s < downs_s[i]) ++k;
    while (k < sink.blocks.size() && !sink.blocks[k].nonzero) ++k;
    ASSERT_LT(k, sink.blocks.size()) << "a tap produced no drive";
    delays_s.push_back(sink.blocks[k].written_at_s - downs_s[i]);
    onset_minus_event_s.push_back(sink.blocks[k].time_s - downs_on_renderer_clock_s[i]);
    while (k < sink.blocks.size() && sink.blocks[k].nonzero) ++k;
  }
  std::sort(onset_minus_event_s.begin(), onset_minus_event_s.end());
  EXPECT_GT(onset_minus_event_s[onset_minus_event_s.size() / 2], -0.003);
  EXPECT_LT(onset_minus_event_s[onset_minus_event_s.size() / 2], 0.005);
  EXPECT_GT(onset_minus_event_s.front(), -0.020);
  EXPECT_LT(onset_minus_event_s.back(), 0.020);
  std::sort(delays_s.begin(), delays_s.end());
  EXPECT_LT(delays_s[delays_s.size() / 2], 0.005);
  EXPECT_LT(delays_s.back(), 0.030);
}

TEST(RealtimePaced, ADeviceClockOnePercentSlowPacesTheRendererAndTapsStillDrive) { tap_on_drifting_device(0.99); }

TEST(RealtimePaced, ADeviceClockOnePercentFastPacesTheRendererAndTapsStillDrive) { tap_on_drifting_device(1.01); }

}  // namespace
}  // namespace vimg
