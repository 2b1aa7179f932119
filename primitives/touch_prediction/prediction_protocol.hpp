#pragma once
// The published test of touch prediction (Henze et al., MobileHCI 2017, their LSTM-Test notebook's
// loadStudyData), so that a predictor is measured on the authors' own samples:
//   - within each run of consecutive moves (a stroke's events between its down and its up), every
//     window of 11 + s moves starting at a move gives one sample when at least its first 12
//     events are moves; when the run ends inside the window, the window is padded with the run's
//     last move (so the target is then that move);
//   - "now" is the window's 11th event, the target the event s later (s = 2, 4, 6: 33, 67 and
//     100 ms at 60 Hz);
//   - a sample with two consecutive window events less than 1 ms apart is dropped;
//   - the error is the Euclidean distance to the target, averaged over the samples.
// Baselines as the authors define them: no extrapolation (the position now) and linear
// extrapolation (now + s x the last step). Our models (finger_predictor.hpp) see every event of
// the stroke from its down up to now and predict at now + s x the nominal event period: the
// horizon a live player with a known latency uses, not the target event's own time.
#include <cstddef>
#include <span>
#include <vector>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg {

struct TouchStroke {
  std::vector<FingerHistory::Point> events;  // the down, the moves, then the up (if recorded)
  bool ends_with_up = true;
};

struct ProtocolErrors {
  std::size_t samples = 0;
  double none_mm = 0.0;            // the authors' no extrapolation
  double authors_linear_mm = 0.0;  // now + s x the last step
  double model_mm[kTouchPredictionModelCount] = {};  // indexed by TouchPredictionModel
};

ProtocolErrors evaluate_prediction_protocol(std::span<const TouchStroke> strokes, int steps_ahead,
                                            double event_period_s = 1.0 / 60.0);

}  // namespace vimg
