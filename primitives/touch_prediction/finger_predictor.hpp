#pragma once
// Where a finger will be: one finger's position at a time after its last touch event, from the
// events of that finger up to now (docs/latency.md). Pure functions over a FingerHistory that the
// caller owns (one per finger, plain data: copies and resets never allocate). No clock: every time
// is the caller's, in seconds on one time base; positions are in mm (any unit works: the models
// are linear in position, and only kBlendFloor_mm assumes mm).
//
// History. add_finger_event() keeps up to kHistoryCapacity points (time, x, y), the newest last:
//   - an event earlier than the newest point takes that point's time (time never runs backwards);
//   - while the newest point is less than kMinSpacing_s after the one before it, a new event
//     replaces it instead of adding a point, so 64 points always span at least 126 ms, whatever
//     the event rate (60 Hz panels, 240 Hz coalesced pointer events, 1 kHz mice).
// Each call is O(1).
//
// Models, for the position at the last event's time t_n plus horizon h >= 0:
//   none:    p(t_n)                                   (the last position)
//   linear:  p(t_n) + v h, v = (p(t_n) - p(t_m)) / (t_n - t_m), t_m the newest stored point at
//            least 1 ms before t_n (v = 0 when there is none): the last velocity.
//   fitted:  p(t_n) + sum_k w_k(h) d_k. d_k = p(t_n - k L) - p(t_n), k = 1..12,
//            L = 1/120 s (100 ms of history), p between stored points linear, and before the
//            first point equal to it (the finger was put down there). The weights are a blend of
//            two least-squares filters fitted on real traces (fitted_weights.hpp, made by
//            scripts/fit_touch_predictor.py):  w = lambda w_exact + (1 - lambda) w_free, with
//              lambda = exp(-rho / kBlendScale),  rho = rms_k |d_k + v_ls k L| / (|v_ls| 12 L + kBlendFloor_mm),
//            v_ls = -sum k d_k / (L sum k^2) the least-squares constant velocity of the history.
//            w_exact satisfies sum_k w_k k L = -h, so a history at constant velocity (rho = 0)
//            is continued exactly; the free filter, which holds back on irregular histories,
//            takes over as the history departs from a straight line. Weights are linear in h
//            between the fitted horizons j L (j = 1..24, w(0) = 0); beyond 200 ms the 200 ms
//            weights are scaled by h / 200 ms (still exact at constant velocity).
//   learned: the default; a small fixed-weight network on the recent steps in the stroke's frame
//            (learned_predictor.hpp).
//
// Bounds (tests/touch_prediction/, docs/touch-prediction.md "What the tests hold it to"):
//   - a still finger (all d_k = 0) is predicted where it is, by every model;
//   - |fitted offset| <= max(sum|w_free|, sum|w_exact|) * max_k |d_k|: no more than a fixed
//     multiple of how far the finger moved in the last 100 ms;
//   - constant acceleration a with velocity v at t_n: error = lambda e_exact + (1 - lambda) e_free,
//     e = v (-sum w_k k L - h) + a/2 (sum w_k k^2 L^2 - h^2), so |error| <= max(|e_exact|, |e_free|);
//   - position noise of standard deviation s on every event: the error is a linear combination
//     sum_i c_i n_i of the events' noises, so its standard deviation is s ||c||_2 (at 120 Hz
//     c = (1 - sum w, w_1..w_12)); noise bounded by s gives at most s ||c||_1;
//   - every model: |offset| <= (h / 1 ms) x the largest distance from the last position to an
//     event since 2 ms before the newest event at least 100 ms old (no offset runs away).
// Silence (the finger stopped: panels send no events while a finger rests) is the caller's
// horizon rule: predict_finger_at() fades the offset to zero as the time since the last event
// grows from kSilenceHold_s to kSilenceStop_s.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace vimg {

enum class TouchPredictionModel : std::uint8_t { none, linear, fitted, learned };
inline constexpr int kTouchPredictionModelCount = 4;

// The best out of sample (docs/touch-prediction.md, "How well it predicts").
inline constexpr TouchPredictionModel kDefaultTouchPredictionModel = TouchPredictionModel::learned;

// "none", "linear", "fitted", "learned".
std::string_view touch_prediction_model_name(TouchPredictionModel model);
std::optional<TouchPredictionModel> parse_touch_prediction_model(std::string_view name);

struct FingerHistory {
  static constexpr int kHistoryCapacity = 64;
  static constexpr double kMinSpacing_s = 0.002;
  struct Point {
    double time_s = 0.0;
    double x_mm = 0.0;
    double y_mm = 0.0;
  };
  std::array<Point, kHistoryCapacity> points{};  // ring
  int newest = -1;                               // index of the newest point; -1: empty
  int count = 0;
};

struct PredictedPosition {
  double x_mm = 0.0;
  double y_mm = 0.0;
};

// Empties the history (a new touch).
void reset_finger_history(FingerHistory& history);
void add_finger_event(FingerHistory& history, double time_s, double x_mm, double y_mm);
bool finger_history_empty(const FingerHistory& history);
// The newest point's time (0 when empty).
double last_finger_event_time_s(const FingerHistory& history);

// The position at last_finger_event_time_s() + horizon_s (horizon_s < 0 counts as 0). An empty
// history gives (0, 0).
PredictedPosition predict_finger(const FingerHistory& history, double horizon_s, TouchPredictionModel model);

// predict_finger() at two horizons of one history, each the same as alone; the learned model
// shares its per-history work between them (learned_predictor.hpp), the others run twice.
std::array<PredictedPosition, 2> predict_finger_pair(const FingerHistory& history, double first_horizon_s,
                                                     double second_horizon_s, TouchPredictionModel model);

inline constexpr double kSilenceHold_s = 0.05;
inline constexpr double kSilenceStop_s = 0.1;

// For a live player: the position at now_s + ahead_s, where now_s >= the last event's time. The
// predicted offset from the last position is scaled by 1 while now_s - t_n <= kSilenceHold_s,
// then linearly down to 0 at kSilenceStop_s: a finger that has sent nothing for 100 ms is where
// it was last seen.
PredictedPosition predict_finger_at(const FingerHistory& history, double now_s, double ahead_s,
                                    TouchPredictionModel model);

}  // namespace vimg
