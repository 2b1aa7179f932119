// predicted_path.hpp: the span's ends are predict_finger_at()'s positions, the learned model's pair
// is its single prediction twice (bit for bit), a model linear in the horizon is followed exactly
// between the ends, interval 0 is predict_finger_at() itself, and a silent finger comes to rest
// exactly where it was last seen, for every model.
#include <gtest/gtest.h>

#include <cmath>

#include "every_model.hpp"
#include "primitives/touch_prediction/circling_finger.hpp"
#include "primitives/touch_prediction/learned_predictor.hpp"
#include "primitives/touch_prediction/predicted_path.hpp"

namespace vimg {
namespace {

TEST(PredictedPath, TheLearnedPairIsTwoSinglePredictionsBitForBit) {
  const FingerHistory h = circling_finger_history();
  for (double h0 : {0.0, 0.008, 0.033, 0.0999}) {
    for (double h1 : {0.0, 0.01, 0.067, 0.1, 0.25}) {
      const auto pair = predict_finger_pair(h, h0, h1, TouchPredictionModel::learned);
      const PredictedPosition a = predict_finger(h, h0, TouchPredictionModel::learned);
      const PredictedPosition b = predict_finger(h, h1, TouchPredictionModel::learned);
      EXPECT_EQ(pair[0].x_mm, a.x_mm);
      EXPECT_EQ(pair[0].y_mm, a.y_mm);
      EXPECT_EQ(pair[1].x_mm, b.x_mm);
      EXPECT_EQ(pair[1].y_mm, b.y_mm);
    }
  }
}

TEST(PredictedPath, TheSpansEndsArePredictFingerAtAndALinearModelIsFollowedExactly) {
  const FingerHistory h = circling_finger_history();
  const double t_n = last_finger_event_time_s(h), ahead_s = 0.04, interval_s = 0.01;
  for (TouchPredictionModel m : test::every_touch_prediction_model()) {
    PredictedPath path;
    double worst_mm = 0.0;
    for (int i = 0; i <= 1600; ++i) {  // 0 to 200 ms of silence at 8 kHz
      const double now_s = t_n + i / 8000.0;
      const PredictedPosition p = predicted_path_at(path, h, now_s, ahead_s, m, interval_s);
      const PredictedPosition r = predict_finger_at(h, now_s, ahead_s, m);
      const double apart_mm = std::hypot(p.x_mm - r.x_mm, p.y_mm - r.y_mm);
      if (i % 80 == 0 || m == TouchPredictionModel::none || m == TouchPredictionModel::linear) {
        ASSERT_LE(apart_mm, 1e-9) << touch_prediction_model_name(m) << " at " << i;  // a span's end (every 10 ms), or exact
      }
      worst_mm = std::max(worst_mm, apart_mm);
      if (now_s - t_n >= kSilenceStop_s) {
        const FingerHistory::Point& last = h.points[static_cast<std::size_t>(h.newest)];
        ASSERT_EQ(p.x_mm, last.x_mm);
        ASSERT_EQ(p.y_mm, last.y_mm);
      }
    }
    // One span per 10 ms of silence until the fade ends (100 ms): 11 horizons, not 800.
    EXPECT_LE(path.predictions, 12) << touch_prediction_model_name(m);
    EXPECT_LE(worst_mm, 0.05) << touch_prediction_model_name(m) << ": between the ends, on a smooth circle";
  }
}

TEST(PredictedPath, IntervalZeroIsPredictFingerAtAtEveryCall) {
  const FingerHistory h = circling_finger_history();
  PredictedPath path;
  for (int i = 0; i < 100; ++i) {
    const double now_s = last_finger_event_time_s(h) + i * 1e-3;
    const PredictedPosition p = predicted_path_at(path, h, now_s, 0.03, TouchPredictionModel::learned, 0.0);
    const PredictedPosition r = predict_finger_at(h, now_s, 0.03, TouchPredictionModel::learned);
    ASSERT_EQ(p.x_mm, r.x_mm);
    ASSERT_EQ(p.y_mm, r.y_mm);
  }
  EXPECT_EQ(path.predictions, 100);
}

TEST(PredictedPath, AResetOrANewHorizonStartsANewSpan) {
  FingerHistory h = circling_finger_history();
  PredictedPath path;
  const double t_n = last_finger_event_time_s(h);
  predicted_path_at(path, h, t_n, 0.03, TouchPredictionModel::learned, 0.01);
  add_finger_event(h, t_n + 0.004, 10.0, 10.0);  // far off the circle
  reset_predicted_path(path);
  const PredictedPosition p = predicted_path_at(path, h, t_n + 0.004, 0.03, TouchPredictionModel::learned, 0.01);
  const PredictedPosition r = predict_finger_at(h, t_n + 0.004, 0.03, TouchPredictionModel::learned);
  EXPECT_EQ(p.x_mm, r.x_mm);
  const PredictedPosition q = predicted_path_at(path, h, t_n + 0.004, 0.05, TouchPredictionModel::learned, 0.01);
  const PredictedPosition s = predict_finger_at(h, t_n + 0.004, 0.05, TouchPredictionModel::learned);
  EXPECT_EQ(q.x_mm, s.x_mm);
  EXPECT_EQ(q.y_mm, s.y_mm);
}

}  // namespace
}  // namespace vimg
