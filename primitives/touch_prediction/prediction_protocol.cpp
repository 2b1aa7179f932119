#include "primitives/touch_prediction/prediction_protocol.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

namespace {

constexpr int kNowIndex = 10;        // the window's 11th event
constexpr int kMinMoves = 12;        // events of the window that must be moves
constexpr double kSameTime_s = 5e-4;  // "less than 1 ms apart" on millisecond stamps

double distance_mm(const FingerHistory::Point& a, double x_mm, double y_mm) {
  return std::hypot(a.x_mm - x_mm, a.y_mm - y_mm);
}

struct Sums {
  double none = 0.0, authors_linear = 0.0, model[kTouchPredictionModelCount] = {};
  std::size_t samples = 0;
};

void evaluate_stroke(const TouchStroke& stroke, int s, double period_s, Sums& sums) {
  const std::vector<FingerHistory::Point>& ev = stroke.events;
  // Moves: ev[1 .. last_move]; the run index r maps to ev[1 + r].
  const int end = static_cast<int>(ev.size()) - (stroke.ends_with_up ? 1 : 0);
  const int moves = end - 1;
  const int window = 11 + s;
  if (moves < kMinMoves) return;
  FingerHistory history;
  int added = 0;  // events of the stroke in the history: the down and the moves up to now
  for (int i = 0; i + kMinMoves <= moves; ++i) {
    const int jump = i + window <= moves ? i + window + 1 : moves;  // first index padded from
    auto at = [&](int k) -> const FingerHistory::Point& { return ev[static_cast<std::size_t>(1 + std::min(k, jump - 1))]; };
    bool same_time = false;
    for (int a = 1; a < window && !same_time; ++a) {
      const int k = i + a;
      const double dt = k >= jump - 1 ? at(jump - 1).time_s - at(jump - 2).time_s : at(k).time_s - at(k - 1).time_s;
      same_time = dt < kSameTime_s;
    }
    if (same_time) continue;
    const FingerHistory::Point& now = at(i + kNowIndex);
    const FingerHistory::Point& before = at(i + kNowIndex - 1);
    const FingerHistory::Point& target = at(i + kNowIndex + s);
    sums.none += distance_mm(target, now.x_mm, now.y_mm);
    sums.authors_linear += distance_mm(target, now.x_mm + s * (now.x_mm - before.x_mm), now.y_mm + s * (now.y_mm - before.y_mm));
    for (; added <= 1 + i + kNowIndex; ++added) {
      const FingerHistory::Point& e = ev[static_cast<std::size_t>(added)];
      add_finger_event(history, e.time_s, e.x_mm, e.y_mm);
    }
    for (int m = 0; m < kTouchPredictionModelCount; ++m) {
      const PredictedPosition p = predict_finger(history, s * period_s, static_cast<TouchPredictionModel>(m));
      sums.model[m] += distance_mm(target, p.x_mm, p.y_mm);
    }
    ++sums.samples;
  }
}

}  // namespace

ProtocolErrors evaluate_prediction_protocol(std::span<const TouchStroke> strokes, int steps_ahead, double event_period_s) {
  Sums sums;
  for (const TouchStroke& stroke : strokes) evaluate_stroke(stroke, steps_ahead, event_period_s, sums);
  ProtocolErrors r;
  r.samples = sums.samples;
  if (sums.samples == 0) return r;
  const double n = static_cast<double>(sums.samples);
  r.none_mm = sums.none / n;
  r.authors_linear_mm = sums.authors_linear / n;
  for (int m = 0; m < kTouchPredictionModelCount; ++m) r.model_mm[m] = sums.model[m] / n;
  return r;
}

}  // namespace vimg
