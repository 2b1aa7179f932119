// The live path with the predictor run per event and interpolated (player/live_tracker.hpp,
// primitives/touch_prediction/predicted_path.hpp), on ten fingers of the shared real traces:
//   - causal: a step at time t is the same whatever events come after t (the same steps, bit for
//     bit, from a tracker that is later given different events);
//   - no runaway: every felt position lies within (h / 1 ms) D of the finger's last event, h the
//     horizon plus the silence since that event, D the largest distance from it to the finger's
//     events back to 2 ms before the newest one at least 100 ms old (docs/touch-prediction.md, "No offset
//     runs away"), through silences of up to 150 ms, and a finger silent for 100 ms is where it
//     was last seen.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "player/live_tracker.hpp"
#include "trace_fingers.hpp"

namespace vimg {
namespace {

constexpr double kHorizon_s = 0.06;
constexpr double kRate_hz = 8000.0;

TEST(LiveCausality, AStepDependsOnlyOnTheEventsBeforeIt) {
  const std::vector<TouchEvent> events = test::ten_trace_fingers();
  const double cut_s = 0.5 * events.back().time_s;
  LiveTracker a, b;
  a.set_prediction(kHorizon_s);
  b.set_prediction(kHorizon_s);
  std::array<FingerStep, LiveTracker::kMaxFingers> sa{}, sb{};
  std::size_t next = 0;
  bool differed_after = false;
  for (long i = 0;; ++i) {
    const double t = static_cast<double>(i) / kRate_hz;
    if (t > events.back().time_s) break;
    while (next < events.size() && events[next].time_s <= t) {
      const TouchEvent& e = events[next++];
      a.apply(e, t);
      TouchEvent other = e;
      if (e.time_s > cut_s && e.phase == TouchPhase::move) other.x_mm += 3.0;  // b's future differs
      b.apply(other, t);
    }
    const std::size_t na = a.steps_at(t, 1.0 / kRate_hz, sa), nb = b.steps_at(t, 1.0 / kRate_hz, sb);
    ASSERT_EQ(na, nb);
    for (std::size_t k = 0; k < na; ++k) {
      const bool same = sa[k].position_m.x == sb[k].position_m.x && sa[k].position_m.y == sb[k].position_m.y;
      if (t <= cut_s) {
        ASSERT_TRUE(same) << "t " << t << " finger " << sa[k].finger;
      } else {
        differed_after |= !same;
      }
    }
  }
  EXPECT_TRUE(differed_after) << "the later events must change the later steps";
}

// D of finger_predictor.hpp for the events of one finger so far (tests/touch_prediction/no_runaway_test.cpp).
double recent_reach_mm(const std::vector<TouchEvent>& events) {
  const TouchEvent& last = events.back();
  double from_s = -std::numeric_limits<double>::infinity();
  for (auto e = events.rbegin(); e != events.rend(); ++e) {
    if (e->time_s <= last.time_s - 0.1 - 1e-9) {
      from_s = e->time_s - FingerHistory::kMinSpacing_s;
      break;
    }
  }
  double reach = 0.0;
  for (auto e = events.rbegin(); e != events.rend() && e->time_s >= from_s; ++e) {
    reach = std::max(reach, std::hypot(e->x_mm - last.x_mm, e->y_mm - last.y_mm));
  }
  return reach;
}

TEST(LiveCausality, NoFeltPositionRunsAwayThroughEventsAndSilences) {
  // Every stroke, and each one again with its moves stopping halfway: the finger rests silent until
  // it lifts.
  const std::vector<TouchEvent> all = test::ten_trace_fingers(true);
  std::array<double, LiveTracker::kMaxFingers> halfway_s{};
  for (const TouchEvent& e : all) {
    auto& h = halfway_s[static_cast<std::size_t>(e.finger)];
    if (e.phase == TouchPhase::down) h = e.time_s;
    if (e.phase == TouchPhase::up) h = 0.5 * (h + e.time_s);
  }
  for (bool cut_short : {false, true}) {
    LiveTracker tracker;
    tracker.set_prediction(kHorizon_s);
    std::array<std::vector<TouchEvent>, LiveTracker::kMaxFingers> seen;
    std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
    std::size_t next = 0, checks = 0, silent = 0;
    for (long i = 0;; ++i) {
      const double t = static_cast<double>(i) / kRate_hz;
      if (next == all.size() && t > all.back().time_s + 0.2) break;
      while (next < all.size() && all[next].time_s <= t) {
        const TouchEvent& e = all[next++];
        auto& mine = seen[static_cast<std::size_t>(e.finger)];
        if (e.phase == TouchPhase::down) mine.clear();
        if (cut_short && e.phase == TouchPhase::move && e.time_s > halfway_s[static_cast<std::size_t>(e.finger)]) continue;
        if (e.phase != TouchPhase::up) mine.push_back(e);
        tracker.apply(e, t);
      }
      const std::size_t n = tracker.steps_at(t, 1.0 / kRate_hz, steps);
      for (std::size_t k = 0; k < n; ++k) {
        const std::vector<TouchEvent>& mine = seen[static_cast<std::size_t>(steps[k].finger)];
        if (mine.empty()) continue;
        const TouchEvent& last = mine.back();
        const double silence_s = std::max(0.0, t - last.time_s);
        const double offset_mm = std::hypot(steps[k].position_m.x * 1e3 - last.x_mm, steps[k].position_m.y * 1e3 - last.y_mm);
        ASSERT_LE(offset_mm, (silence_s + kHorizon_s) * 1000.0 * recent_reach_mm(mine) + 1e-6) << "t " << t;
        if (silence_s > kSilenceStop_s) {
          ++silent;
          ASSERT_LE(offset_mm, 1e-9) << "a finger silent for 100 ms is where it was last seen, t " << t;
        }
        ++checks;
      }
    }
    EXPECT_GT(checks, 100000u);
    if (cut_short) {
      EXPECT_GT(silent, 1000u);
    }
  }
}

}  // namespace
}  // namespace vimg
