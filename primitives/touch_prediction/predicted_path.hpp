#pragma once
// A finger's predicted position as a cheap function of time, for a live player that needs it at
// every output sample (docs/latency.md, "What the players do"). predict_finger_at() at each sample
// runs the model once per sample and finger (the learned network, 2 400 multiply-adds, 48 000
// times a second per finger at 48 kHz); predicted_path_at() runs it at the two ends of a span of
// interval_s and interpolates in between. Pure, with caller-owned state (one PredictedPath per
// finger, plain data), as the shaders keep theirs in a ShaderState.
//
// Between two events the history is fixed, so predict_finger_at(history, t, ahead) is
//   p(t) = p_n + fade(s) o(s + ahead),  s = max(t, t_n) - t_n,  o(h) = predict_finger(h) - p_n,
// p_n, t_n the newest point, fade the silence rule (1 up to kSilenceHold_s, 0 from kSilenceStop_s).
// predicted_path_at() gives
//   p_n + fade(s) [(1 - a) o(s0 + ahead) + a o(s1 + ahead)],  a = (s - s0) / (s1 - s0),
// on the span [s0, s1] that holds s: the model's offsets at the span's ends, interpolated linearly,
// and the fade applied exactly at s. A span starts at the first call after an event (s0 = that
// call's s, s1 = s0 + interval_s, at most kSilenceStop_s); both ends come from one
// predict_finger_pair(). When no event comes within it, the next span [s1, s1 + interval_s] costs
// one prediction (its start is the previous end). So the model runs for two horizons per event
// (about 1.5 predictions' cost with the learned model) and for one per interval_s of silence, never
// once the fade is 0. The default span, 10 ms, holds the next event of a 120 Hz panel.
// What holds, by construction (tests/touch_prediction/predicted_path_test.cpp):
//   - at a span's ends, the same position as predict_finger_at() (to rounding); interval_s <= 0 (or
//     not finite) calls predict_finger_at() at every call (the reference);
//   - a model whose offset is linear in the horizon (none, linear, and learned at a constant
//     velocity) is reproduced at every time (to rounding); otherwise the error is what linear
//     interpolation over a span leaves of o(h): the learned network is piecewise linear in h with
//     kinks, so on real traces the largest errors are a fraction of a millimetre and the mean a
//     few micrometres (docs/latency.md, "What the players do");
//   - no runaway: each end's offset is within (h / 1 ms) D (finger_predictor.hpp), h is linear in
//     s over the span, so the interpolated offset is within it at every s; the fade only shrinks it,
//     and a finger silent for kSilenceStop_s is exactly where it was last seen;
//   - causal: only the history given (its events up to now) is used.
// The caller calls reset_predicted_path() whenever the history changes (every add_finger_event(),
// reset_finger_history()); a change of ahead_s, model or interval_s is noticed here.
#include <algorithm>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg {

// The span a live player interpolates over (LiveTrackerOptions::prediction_interval_s).
inline constexpr double kDefaultPredictionInterval_s = 0.01;

struct PredictedPath {
  bool valid = false;
  double ahead_s = 0.0;
  double interval_s = 0.0;
  TouchPredictionModel model = TouchPredictionModel::none;
  FingerHistory::Point last;         // the history's newest point when the span was made
  double from_s = 0.0;               // the span, in silence s (time since `last`)
  double to_s = 0.0;
  PredictedPosition from_offset_mm;  // o(from_s + ahead_s)
  PredictedPosition to_offset_mm;    // o(to_s + ahead_s)
  PredictedPosition slope_mm_per_s;  // (to_offset - from_offset) / (to_s - from_s)
  int predictions = 0;  // horizons the model was run for since the last reset (tests, benchmarks)
};

void reset_predicted_path(PredictedPath& path);

// The slow path of predicted_path_at(): makes or moves the span, or calls predict_finger_at().
PredictedPosition predicted_path_update(PredictedPath& path, const FingerHistory& history, double now_s,
                                        double ahead_s, TouchPredictionModel model, double interval_s);

// The position at now_s + ahead_s, as predict_finger_at(history, now_s, ahead_s, model), from the
// span that holds now_s (made or moved on here). An empty history gives (0, 0). Inline: at most
// samples it is two multiply-adds.
inline PredictedPosition predicted_path_at(PredictedPath& path, const FingerHistory& history, double now_s,
                                           double ahead_s, TouchPredictionModel model, double interval_s) {
  if (path.valid && path.ahead_s == ahead_s && path.model == model && path.interval_s == interval_s) {
    const double s = std::max(0.0, now_s - path.last.time_s);
    if (s >= path.from_s && s <= path.to_s && s <= kSilenceHold_s) {
      const double d = s - path.from_s;
      return {path.last.x_mm + (path.from_offset_mm.x_mm + d * path.slope_mm_per_s.x_mm),
              path.last.y_mm + (path.from_offset_mm.y_mm + d * path.slope_mm_per_s.y_mm)};
    }
  }
  return predicted_path_update(path, history, now_s, ahead_s, model, interval_s);
}

}  // namespace vimg
