// `vimg gesture predict`'s rows (player/gesture_prediction.hpp): causal (each row predicted from its
// stroke's rows up to it alone), down and up rows at their own position, one row per input row.
#include <gtest/gtest.h>

#include <cmath>

#include "every_model.hpp"
#include "player/gesture_prediction.hpp"

namespace vimg {
namespace {

Gesture curved_gesture(double end_s) {
  Gesture g;
  for (int finger = 0; finger < 2; ++finger) {
    GestureStroke s;
    s.finger = finger;
    for (double t = 0.01 * finger; t <= end_s + 1e-9; t += 1.0 / 60.0) {
      s.points.push_back({t, 20.0 + 15.0 * std::cos(3.0 * t + finger), 30.0 + 15.0 * std::sin(3.0 * t), 1.0});
    }
    g.strokes.push_back(s);
  }
  return g;
}

// Causal: every row k between a stroke's down and up is the prediction from that stroke's rows
// 0..k alone (a history holding nothing later), at the horizon asked for, for every model.
TEST(GesturePrediction, EveryRowIsThePredictionFromItsStrokesRowsUpToItAlone) {
  const Gesture whole = curved_gesture(1.0);
  for (TouchPredictionModel m : test::every_touch_prediction_model()) {
    for (double ahead_s : {0.033, 0.067}) {
      const std::vector<PredictedGestureRow> rows = predict_gesture(whole, ahead_s, m);
      std::size_t compared = 0;
      for (const GestureStroke& s : whole.strokes) {
        for (std::size_t k = 1; k + 1 < s.points.size(); ++k) {
          FingerHistory prefix;
          for (std::size_t i = 0; i <= k; ++i) add_finger_event(prefix, s.points[i].time_s, s.points[i].x_mm, s.points[i].y_mm);
          const PredictedPosition expected = predict_finger(prefix, ahead_s, m);
          for (const PredictedGestureRow& r : rows) {
            if (r.finger != s.finger || r.time_s != s.points[k].time_s) continue;
            EXPECT_EQ(r.predicted_x_mm, expected.x_mm) << touch_prediction_model_name(m) << " row " << k;
            EXPECT_EQ(r.predicted_y_mm, expected.y_mm) << touch_prediction_model_name(m) << " row " << k;
            ++compared;
          }
        }
      }
      EXPECT_EQ(compared, rows.size() - 2 * whole.strokes.size());
    }
  }
}

TEST(GesturePrediction, DownAndUpRowsGiveTheirOwnPositionAndEveryRowComesOut) {
  const Gesture g = curved_gesture(0.5);
  const std::vector<PredictedGestureRow> rows = predict_gesture(g, 0.1, TouchPredictionModel::fitted);
  std::size_t n = 0;
  for (const GestureStroke& s : g.strokes) n += s.points.size();
  ASSERT_EQ(rows.size(), n);
  for (const GestureStroke& s : g.strokes) {
    for (const GesturePoint* p : {&s.points.front(), &s.points.back()}) {
      bool found = false;
      for (const PredictedGestureRow& r : rows) {
        if (r.finger == s.finger && r.time_s == p->time_s) {
          EXPECT_EQ(r.predicted_x_mm, p->x_mm);
          EXPECT_EQ(r.predicted_y_mm, p->y_mm);
          found = true;
        }
      }
      EXPECT_TRUE(found);
    }
  }
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_LE(rows[i - 1].time_s, rows[i].time_s);
  // A moving row is predicted ahead of itself: on a circle of radius 15 mm at 3 rad/s (45 mm/s),
  // 100 ms ahead is about 4.5 mm away.
  const PredictedGestureRow& mid = rows[rows.size() / 2];
  EXPECT_GT(std::hypot(mid.predicted_x_mm - mid.x_mm, mid.predicted_y_mm - mid.y_mm), 2.0);
}

}  // namespace
}  // namespace vimg
