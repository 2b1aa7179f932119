// `vimg gesture predict`'s rows (player/gesture_prediction.hpp): causal (a cut gesture predicts its
// rows as the whole one does), down and up rows at their own position, one row per input row.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(GesturePrediction, CuttingTheGestureNeverChangesAnEarlierRow) {
  const Gesture whole = curved_gesture(1.0);
  for (TouchPredictionModel m : {TouchPredictionModel::none, TouchPredictionModel::linear, TouchPredictionModel::fitted}) {
    const std::vector<PredictedGestureRow> all = predict_gesture(whole, 0.067, m);
    Gesture cut = whole;
    for (GestureStroke& s : cut.strokes) s.points.resize(s.points.size() / 2);
    const std::vector<PredictedGestureRow> part = predict_gesture(cut, 0.067, m);
    std::size_t compared = 0;
    for (const PredictedGestureRow& p : part) {
      const GestureStroke& stroke = cut.strokes[static_cast<std::size_t>(p.finger)];
      if (p.time_s == stroke.points.back().time_s) continue;  // the cut's last row is its up: its own position
      for (const PredictedGestureRow& a : all) {
        if (a.finger != p.finger || a.time_s != p.time_s) continue;
        EXPECT_EQ(a.predicted_x_mm, p.predicted_x_mm);
        EXPECT_EQ(a.predicted_y_mm, p.predicted_y_mm);
        ++compared;
      }
    }
    EXPECT_GT(compared, 50u);
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
