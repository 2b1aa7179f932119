// Live input end to end: touch events from another thread, real shaders, the real-time thread.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "player/drive_sinks.hpp"
#include "player/realtime_renderer.hpp"
#include "render_support.hpp"

namespace vimg {
namespace {

TEST(RealtimeLive, AFingerMovingOverASurfaceGivesSpeedOverPeriod) {
  // 100 mm/s over a 2 mm period: 50 Hz, events at 120 Hz with the thread's own timing.
  const Image img = test::image_of({test::element("s", test::rect_surface(0, 0, 200, 100, 2.0, 0.5, 0.4))});
  MemorySink sink(8000 * 5);
  RealtimeRenderer r(sink);
  r.set_scene(compile_scene(img));
  ASSERT_FALSE(r.start());
  const double t0 = monotonic_s();
  r.push_event({t0, 0, TouchPhase::down, 10.0, 50.0, 1.0});
  double t = t0;
  while (t - t0 < 0.8) {
    std::this_thread::sleep_for(std::chrono::microseconds(8333));
    t = monotonic_s();
    r.push_event({t, 0, TouchPhase::move, 10.0 + 100.0 * (t - t0), 50.0, 1.0});
  }
  r.push_event({t, 0, TouchPhase::up, 10.0 + 100.0 * (t - t0), 50.0, 1.0});
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  r.stop();
  test::Rendered out{sink.samples(), 8000.0, 0.0};
  // The touch starts within the first blocks; measure well inside the stroke.
  const auto span = out.nonzero_span(0.0, 100.0);
  ASSERT_TRUE(span.has_value());
  EXPECT_NEAR(out.zero_crossing_frequency_hz(span->first + 0.15, span->first + 0.65), 50.0, 50.0 * 0.05);
  EXPECT_EQ(sink.samples().back(), 0.0f);
}

}  // namespace
}  // namespace vimg
