// "No offset runs away" (docs/touch-prediction.md, "The predictor"), for every model of the enum: on random
// stop-and-go strokes with jittered event times (bursts a fraction of a millisecond apart, gaps,
// silences) and jittered positions, every prediction h ahead of the last event lies within
// (h / 1 ms) x D of the last position, D the largest distance from the last position to an event
// of the recent past (recent_reach_mm below). So a finger that stops is predicted where it is once
// it has rested 100 ms, and a silent finger once predict_finger_at() has faded the offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>

#include "every_model.hpp"
#include "fitted_reference.hpp"

namespace vimg {
namespace {

using test::TouchEvent;

constexpr double kRecent_s = 0.1;
constexpr double kGainPerSecond = 1.0 / 0.001;  // (h / 1 ms): the bound's multiple of D

// D: the largest distance from the last event to any event from 2 ms (the history's minimum
// spacing) before the newest event at least 100 ms old (every event when there is none).
double recent_reach_mm(const std::vector<TouchEvent>& events) {
  const TouchEvent& last = events.back();
  double from_s = -std::numeric_limits<double>::infinity();
  for (auto e = events.rbegin(); e != events.rend(); ++e) {
    if (e->time_s <= last.time_s - kRecent_s - 1e-9) {
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

// A stroke of moves and stops. Event gaps: mostly 4-20 ms, some bursts of 0.05-1.5 ms (coalesced
// or bursty pointer events), some 20-80 ms; a stop is sometimes silent (no events at all).
// Positions jitter by up to `jitter_mm` while the finger moves (a still finger reports its place).
std::vector<TouchEvent> stop_and_go_stroke(std::mt19937& rng, double jitter_mm) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<TouchEvent> events;
  double t = 5.0 * unit(rng), x = 100.0 * unit(rng), y = 100.0 * unit(rng);
  auto gap_s = [&] {
    const double u = unit(rng);
    if (u < 0.7) return 0.004 + 0.016 * unit(rng);
    if (u < 0.9) return 0.00005 + 0.00145 * unit(rng);
    return 0.02 + 0.06 * unit(rng);
  };
  events.push_back({t, x, y});
  const int segments = 3 + static_cast<int>(6 * unit(rng));
  for (int segment = 0; segment < segments; ++segment) {
    const bool moving = segment % 2 == 0;
    const double duration_s = 0.02 + 0.38 * unit(rng);
    const double speed = moving ? 20.0 + 580.0 * unit(rng) : 0.0, turn = 20.0 * (unit(rng) - 0.5);
    double heading = 2.0 * std::numbers::pi * unit(rng);
    if (!moving && unit(rng) < 0.3) {  // a silent rest, then the finger goes on from there
      t += duration_s;
      continue;
    }
    for (double end_s = t + duration_s; t < end_s;) {
      const double dt = gap_s();
      t += dt;
      heading += turn * dt;
      x += speed * dt * std::cos(heading);
      y += speed * dt * std::sin(heading);
      const double jx = moving ? jitter_mm * (2.0 * unit(rng) - 1.0) : 0.0;
      const double jy = moving ? jitter_mm * (2.0 * unit(rng) - 1.0) : 0.0;
      events.push_back({t, x + jx, y + jy});
    }
  }
  return events;
}

TEST(NoOffsetRunsAway, EveryModelStaysWithinTheBoundOnStopAndGoAndJitteredStrokes) {
  const std::vector<TouchPredictionModel> models = test::every_touch_prediction_model();
  ASSERT_GE(models.size(), 3u);
  const double horizons_s[] = {0.0, 0.004, 0.0167, 0.033, 0.067, 0.1, 0.25};
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t checks = 0, violations = 0, rests = 0, silences = 0;
  std::map<std::string, std::size_t> violations_of;  // per model
  std::string first_violation;
  auto check = [&](bool ok, auto describe) {
    ++checks;
    if (ok) return;
    const std::string what = describe();
    ++violations_of[what.substr(0, what.find(' '))];
    if (violations++ == 0) first_violation = what;
  };
  for (int stroke = 0; stroke < 300; ++stroke) {
    const double jitter_mm = stroke % 3 == 0 ? 0.0 : stroke % 3 == 1 ? 0.05 : 0.5;
    const std::vector<TouchEvent> all = stop_and_go_stroke(rng, jitter_mm);
    std::vector<TouchEvent> events;
    FingerHistory history;
    for (const TouchEvent& e : all) {
      events.push_back(e);
      add_finger_event(history, e.time_s, e.x_mm, e.y_mm);
      const double reach = recent_reach_mm(events);
      if (reach == 0.0 && events.size() > 20) ++rests;
      for (TouchPredictionModel m : models) {
        const std::string_view name = touch_prediction_model_name(m);
        for (double h : horizons_s) {
          const PredictedPosition p = predict_finger(history, h, m);
          const double offset = std::hypot(p.x_mm - e.x_mm, p.y_mm - e.y_mm);
          check(offset <= kGainPerSecond * h * reach + 1e-9, [&] {
            return std::string(name) + " h " + std::to_string(h) + " offset " + std::to_string(offset) + " D " + std::to_string(reach) +
                   " stroke " + std::to_string(stroke) + " event " + std::to_string(events.size());
          });
          if (m == TouchPredictionModel::fitted) {  // the header's own, tighter bound
            const double gain = std::max(test::sum_abs(test::fitted_weights_at(touch_prediction::kFreeWeights, h)),
                                         test::sum_abs(test::fitted_weights_at(touch_prediction::kExactWeights, h)));
            check(offset <= gain * reach * (1.0 + 1e-9) + 1e-9, [&] { return "fitted (the header's bound) h " + std::to_string(h); });
          }
        }
        // A live player between events: the horizon grows with the silence, and a finger silent
        // for 100 ms is where it was last seen.
        const double silence_s = 0.15 * unit(rng), ahead_s = 0.1 * unit(rng);
        const PredictedPosition p = predict_finger_at(history, e.time_s + silence_s, ahead_s, m);
        const double offset = std::hypot(p.x_mm - e.x_mm, p.y_mm - e.y_mm);
        check(offset <= kGainPerSecond * (silence_s + ahead_s) * reach + 1e-9, [&] { return std::string(name) + " live"; });
        if (silence_s > kSilenceStop_s) {
          ++silences;
          check(offset == 0.0, [&] { return std::string(name) + " silent " + std::to_string(silence_s) + " s, offset " + std::to_string(offset); });
        }
      }
    }
  }
  std::string per_model;
  for (const auto& [model, n] : violations_of) per_model += " " + model + ": " + std::to_string(n);
  EXPECT_EQ(violations, 0u) << "of " << checks << " checks (" << per_model << " ); the first: " << first_violation;
  // The strokes did rest (D = 0 after motion) and fall silent, so both returns were exercised.
  EXPECT_GT(rests, 500u);
  EXPECT_GT(silences, 1000u);
}

}  // namespace
}  // namespace vimg
