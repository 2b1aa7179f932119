// Touch-latency compensation on the live path (player/live_tracker.hpp, realtime_renderer.hpp):
// the tracker predicts each finger its horizon ahead on the caller's clock, never past a lift and
// never away when the finger stops sending events; the renderer's horizon is the panel's latency
// plus the sink's own output latency.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "player/live_tracker.hpp"
#include "player/realtime_renderer.hpp"
#include "fake_device_sink.hpp"

namespace vimg {
namespace {

constexpr double kSpeed_mm_per_s = 150.0;

double path_x_mm(double t) { return 10.0 + kSpeed_mm_per_s * t; }

// Events of one finger moving along x at 60 Hz from t = 0 to `until_s`, stamped as they arrive.
void feed(LiveTracker& tracker, double until_s) {
  tracker.apply({0.0, 0, TouchPhase::down, path_x_mm(0.0), 5.0, 1.0}, 0.0);
  for (int i = 1; i / 60.0 <= until_s + 1e-12; ++i) {
    const double t = i / 60.0;
    tracker.apply({t, 0, TouchPhase::move, path_x_mm(t), 5.0, 1.0}, t);
  }
}

FingerStep one_step(LiveTracker& tracker, double t) {
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  const std::size_t n = tracker.steps_at(t, 1.0 / 8000.0, steps);
  EXPECT_EQ(n, 1u);
  return steps[0];
}

TEST(LivePrediction, AFingerAtConstantVelocityIsFeltWhereItIsAfterTheHorizon) {
  for (double horizon_s : {0.03, 0.06, 0.1}) {
    LiveTracker tracker;
    tracker.set_prediction(horizon_s);
    feed(tracker, 0.5);
    for (double t : {0.5, 0.505, 0.51, 0.515}) {
      const FingerStep s = one_step(tracker, t);
      EXPECT_NEAR(s.position_m.x * 1e3, path_x_mm(t + horizon_s), 1e-6) << "horizon " << horizon_s << " t " << t;
    }
  }
}

TEST(LivePrediction, WithoutAHorizonTheTrackerFollowsTheLateEvents) {
  LiveTracker tracker;
  feed(tracker, 0.5);
  EXPECT_NEAR(one_step(tracker, 0.5).position_m.x * 1e3, path_x_mm(0.5), 1e-6);
}

TEST(LivePrediction, ALiftEndsTheTouchWhereItIsFeltAndNothingComesAfter) {
  LiveTracker tracker;
  tracker.set_prediction(0.08);
  feed(tracker, 0.5);
  const double felt_mm = one_step(tracker, 0.51).position_m.x * 1e3;
  EXPECT_GT(felt_mm, path_x_mm(0.5) + 10.0);  // 80 ms ahead at 150 mm/s: 12 mm past the last event
  tracker.apply({0.52, 0, TouchPhase::up, path_x_mm(0.52), 5.0, 1.0}, 0.52);
  const FingerStep last = one_step(tracker, 0.52);
  EXPECT_EQ(last.position_m.x * 1e3, felt_mm) << "the final step stays where the touch was felt";
  EXPECT_EQ(last.previous_position_m.x * 1e3, felt_mm);
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  EXPECT_EQ(tracker.steps_at(0.53, 1.0 / 8000.0, steps), 0u);
}

TEST(LivePrediction, AFingerThatStopsSendingEventsComesToRestWhereItWasLastSeen) {
  LiveTracker tracker;
  tracker.set_prediction(0.1);
  feed(tracker, 0.5);
  double farthest_mm = 0.0;
  for (double t = 0.5; t < 1.5; t += 0.001) farthest_mm = std::max(farthest_mm, one_step(tracker, t).position_m.x * 1e3);
  // Bounded: never beyond the constant-velocity continuation over horizon + the 50 ms hold.
  EXPECT_LE(farthest_mm, path_x_mm(0.5) + kSpeed_mm_per_s * (0.1 + kSilenceHold_s) + 1e-6);
  EXPECT_DOUBLE_EQ(one_step(tracker, 0.5 + kSilenceStop_s + 1e-6).position_m.x * 1e3, path_x_mm(0.5));
  EXPECT_DOUBLE_EQ(one_step(tracker, 1.5).position_m.x * 1e3, path_x_mm(0.5));
}

TEST(LivePrediction, TheFingersVelocityIsReportedAsLongAsThePredictionFollowsIt) {
  // Events that arrive late (stamped 60 ms before the step, as a page stamps a sample by its age)
  // must still give speed-dependent shaders the finger's velocity, whatever the model.
  for (TouchPredictionModel model : {TouchPredictionModel::none, TouchPredictionModel::fitted}) {
    LiveTracker tracker;
    tracker.set_prediction(0.05, model);
    feed(tracker, 0.5);
    EXPECT_NEAR(one_step(tracker, 0.56).velocity_m_per_s.x, kSpeed_mm_per_s * 1e-3, 1e-3) << touch_prediction_model_name(model);
    EXPECT_EQ(one_step(tracker, 0.5 + kSilenceStop_s + 0.01).velocity_m_per_s.x, 0.0);
  }
}

TEST(LivePrediction, TheRenderersHorizonIsThePanelsLatencyPlusTheSinksOwn) {
  for (bool enabled : {true, false}) {
    test::FakeDeviceSink sink(1.0, 400);  // 400 samples queued at 8 kHz: 50 ms
    RealtimeOptions options;
    options.touch.enabled = enabled;
    options.touch.panel_latency_s = 0.03;
    RealtimeRenderer renderer(sink, options);
    ASSERT_FALSE(renderer.start().has_value());
    const double horizon_s = renderer.stats().prediction_horizon_s;
    renderer.stop();
    EXPECT_DOUBLE_EQ(horizon_s, enabled ? 0.03 + 0.05 : 0.0);
  }
}

}  // namespace
}  // namespace vimg
