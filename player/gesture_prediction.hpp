#pragma once
// A gesture's rows with where the touch predictor puts each finger `ahead_s` later (`vimg gesture
// predict`, docs/latency.md). Causal: a row's prediction uses that row and the earlier rows of its
// stroke only, so cutting the file never changes an earlier row's prediction.
//   - a down row predicts its own position (nothing is known of the motion yet);
//   - an up row predicts its own position: the finger leaves there, and nothing is predicted past
//     a lift;
//   - every other row: predict_finger(history up to the row, ahead_s, model).
// Rows come out in the order write_gesture_csv() writes them (time order, ties by stroke).
#include <vector>

#include "storage/gesture_csv.hpp"
#include "primitives/touch_prediction/finger_predictor.hpp"
#include "primitives/touch_prediction/prediction_protocol.hpp"
#include "storage/gesture_prediction_csv.hpp"

namespace vimg {

std::vector<PredictedGestureRow> predict_gesture(const Gesture& gesture, double ahead_s, TouchPredictionModel model);

// The strokes as the prediction protocol takes them (positions in mm, times in s).
std::vector<TouchStroke> touch_strokes_of(const Gesture& gesture);

}  // namespace vimg
