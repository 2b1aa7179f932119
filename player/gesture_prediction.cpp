#include "player/gesture_prediction.hpp"

#include <algorithm>

namespace vimg {

std::vector<PredictedGestureRow> predict_gesture(const Gesture& gesture, double ahead_s, TouchPredictionModel model) {
  std::vector<PredictedGestureRow> rows;
  FingerHistory history;
  for (const GestureStroke& stroke : gesture.strokes) {
    reset_finger_history(history);
    for (std::size_t i = 0; i < stroke.points.size(); ++i) {
      const GesturePoint& p = stroke.points[i];
      add_finger_event(history, p.time_s, p.x_mm, p.y_mm);
      const bool own_position = i == 0 || i + 1 == stroke.points.size();
      const PredictedPosition q = own_position ? PredictedPosition{p.x_mm, p.y_mm} : predict_finger(history, ahead_s, model);
      rows.push_back({p.time_s, stroke.finger, p.x_mm, p.y_mm, q.x_mm, q.y_mm});
    }
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const PredictedGestureRow& a, const PredictedGestureRow& b) { return a.time_s < b.time_s; });
  return rows;
}

std::vector<TouchStroke> touch_strokes_of(const Gesture& gesture) {
  std::vector<TouchStroke> strokes;
  strokes.reserve(gesture.strokes.size());
  for (const GestureStroke& s : gesture.strokes) {
    TouchStroke t;
    t.events.reserve(s.points.size());
    for (const GesturePoint& p : s.points) t.events.push_back({p.time_s, p.x_mm, p.y_mm});
    strokes.push_back(std::move(t));
  }
  return strokes;
}

}  // namespace vimg
