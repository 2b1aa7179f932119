#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "player/live_tracker.hpp"

namespace vimg {
namespace {

TouchEvent ev(double t, int finger, TouchPhase phase, double x_mm, double y_mm) {
  TouchEvent e;
  e.time_s = t;
  e.finger = finger;
  e.phase = phase;
  e.x_mm = x_mm;
  e.y_mm = y_mm;
  return e;
}

TEST(LiveTracker, IrregularJitteryEventsGiveASteadyVelocity) {
  LiveTracker tracker;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.004, 0.004);
  const double speed = 100.0;  // mm/s along x
  tracker.apply(ev(0.0, 0, TouchPhase::down, 0, 0), 0.0);
  std::array<FingerStep, LiveTracker::kMaxFingers> out{};
  double t = 0.0;
  double worst = 0.0;
  for (int k = 1; k <= 120; ++k) {
    t = k / 120.0 + jitter(rng);  // irregular timestamps, exact positions for them
    tracker.apply(ev(t, 0, TouchPhase::move, speed * t, 0), t);
    const std::size_t n = tracker.steps_at(t + 0.004, 1.0 / 8000, out);
    ASSERT_EQ(n, 1u);
    if (k > 20) worst = std::max(worst, std::fabs(out[0].velocity_m_per_s.x - 0.1) / 0.1);
  }
  EXPECT_LT(worst, 0.02);
  EXPECT_NEAR(out[0].position_m.x, (t + 0.004) * 0.1, 1e-4);  // reckoned ahead of the last event
}

TEST(LiveTracker, PositionNoiseIsSmoothedInTheVelocity) {
  LiveTracker tracker;
  std::mt19937 rng(9);
  std::normal_distribution<double> noise(0.0, 0.05);  // mm
  tracker.apply(ev(0.0, 0, TouchPhase::down, 0, 0), 0.0);
  std::array<FingerStep, LiveTracker::kMaxFingers> out{};
  double raw_worst = 0.0, filtered_worst = 0.0, prev_x = 0.0;
  for (int k = 1; k <= 240; ++k) {
    const double t = k / 240.0;
    const double x = 50.0 * t + noise(rng);
    tracker.apply(ev(t, 0, TouchPhase::move, x, 0), t);
    tracker.steps_at(t, 1.0 / 8000, out);
    if (k > 40) {
      raw_worst = std::max(raw_worst, std::fabs((x - prev_x) * 240.0 * 1e-3 - 0.05));
      filtered_worst = std::max(filtered_worst, std::fabs(out[0].velocity_m_per_s.x - 0.05));
    }
    prev_x = x;
  }
  EXPECT_LT(filtered_worst, 0.5 * raw_worst);
}

TEST(LiveTracker, ExtrapolationIsCappedAndAStillFingerReportsNoVelocity) {
  LiveTrackerOptions o;
  o.max_extrapolation_s = 0.03;
  LiveTracker tracker(o);
  tracker.apply(ev(0.0, 0, TouchPhase::down, 0, 0), 0.0);
  tracker.apply(ev(0.01, 0, TouchPhase::move, 1, 0), 0.01);
  std::array<FingerStep, LiveTracker::kMaxFingers> out{};
  tracker.steps_at(0.02, 0.001, out);
  EXPECT_NEAR(out[0].position_m.x, 0.002, 1e-9);
  EXPECT_NEAR(out[0].velocity_m_per_s.x, 0.1, 1e-9);
  tracker.steps_at(0.5, 0.001, out);
  EXPECT_NEAR(out[0].position_m.x, 0.001 + 0.1 * 0.03, 1e-9);  // held at the cap
  EXPECT_EQ(out[0].velocity_m_per_s.x, 0.0);
}

TEST(LiveTracker, StaleEventsAreDroppedButLiftsAlwaysApply) {
  LiveTracker tracker;
  std::array<FingerStep, LiveTracker::kMaxFingers> out{};
  EXPECT_FALSE(tracker.apply(ev(0.0, 0, TouchPhase::down, 0, 0), 1.0));  // 1 s late
  EXPECT_EQ(tracker.steps_at(1.0, 0.001, out), 0u);
  EXPECT_TRUE(tracker.apply(ev(1.0, 0, TouchPhase::down, 0, 0), 1.0));
  EXPECT_TRUE(tracker.apply(ev(1.0, 0, TouchPhase::up, 2, 0), 5.0));
  // The lift is reported once, at the lift position, then the finger is gone.
  ASSERT_EQ(tracker.steps_at(5.0, 0.001, out), 1u);
  EXPECT_NEAR(out[0].position_m.x, 0.002, 1e-12);
  EXPECT_EQ(tracker.steps_at(5.001, 0.001, out), 0u);
  EXPECT_EQ(tracker.dropped_events(), 1u);
}

TEST(LiveTracker, TenFingersAreTrackedAndAnEleventhIsRefused) {
  LiveTracker tracker;
  for (int f = 0; f < 10; ++f) EXPECT_TRUE(tracker.apply(ev(0.0, f, TouchPhase::down, f, 0), 0.0));
  EXPECT_FALSE(tracker.apply(ev(0.0, 10, TouchPhase::down, 0, 0), 0.0));
  std::array<FingerStep, LiveTracker::kMaxFingers> out{};
  ASSERT_EQ(tracker.steps_at(0.001, 0.001, out), 10u);
  for (int f = 0; f < 10; ++f) EXPECT_NEAR(out[static_cast<std::size_t>(f)].position_m.x, f * 1e-3, 1e-12);
  // A new touch of the same finger gets a new touch id.
  const auto first_id = out[3].touch_id;
  tracker.apply(ev(0.002, 3, TouchPhase::up, 3, 0), 0.002);
  tracker.apply(ev(0.003, 3, TouchPhase::down, 3, 0), 0.003);
  tracker.steps_at(0.004, 0.001, out);
  EXPECT_NE(out[3].touch_id, first_id);
}

TEST(LiveTracker, TheStepStartsWhereThePreviousOneEnded) {
  LiveTracker tracker;
  tracker.apply(ev(0.0, 0, TouchPhase::down, 0, 0), 0.0);
  std::array<FingerStep, LiveTracker::kMaxFingers> out{};
  tracker.steps_at(0.001, 0.001, out);
  const Vec3 last = out[0].position_m;
  tracker.apply(ev(0.01, 0, TouchPhase::move, 5, 0), 0.01);
  tracker.steps_at(0.011, 0.001, out);
  EXPECT_EQ(out[0].previous_position_m, last);  // a continuous path for the shaders
}

}  // namespace
}  // namespace vimg
