#pragma once
// Interaction points from live, jittery, irregularly timed events (up to 10 fingers).
//
// Velocity: each event gives a raw velocity (displacement / event interval). It is smoothed by a
// first-order low-pass whose weight depends on the real interval, a = 1 - exp(-dt / tau), so
// irregular timing is handled exactly; an event closer than min_interval_s to the
// previous velocity anchor updates the position only, and the next raw velocity spans both.
// Position between events: dead reckoning from the last event with the filtered velocity, for at
// most max_extrapolation_s, then held. When the next event arrives the position continues from the
// reckoned point towards it over the following step, so the path stays continuous.
// Stale events (older than stale_after_s at the time they are applied) are dropped, except `up`.
//
// Touch-latency compensation (docs/latency.md): with a prediction horizon H > 0
// (set_prediction()), the position at step time t is the finger predictor's position at t + H
// (primitives/touch_prediction/finger_predictor.hpp, predict_finger_at: from each finger's own
// events, fading back to the last position after 50-100 ms without events). H is the touch
// panel's latency plus the output path's (RealtimeRenderer sets it from its options and the
// sink). A lift ends the touch at once where it is felt: its final step ends at the position
// already rendered, so nothing is rendered past the lift, not even the way back to the up event's
// position. While the prediction follows a finger (up to kSilenceStop_s after its last event) its
// filtered velocity is reported, so late-stamped events still drive speed-dependent shaders.
// The model runs twice per event and once per prediction_interval_s of silence, not once per step:
// between its runs the position follows the predicted offset interpolated linearly in time, the
// silence fade applied at each step (primitives/touch_prediction/predicted_path.hpp); 0 runs
// predict_finger_at() at every step (the reference the interpolation is tested against).
// H = 0 (the default) keeps the dead reckoning above.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "player/finger_step.hpp"
#include "player/render_defaults.hpp"
#include "player/touch_event.hpp"
#include "primitives/touch_prediction/finger_predictor.hpp"
#include "primitives/touch_prediction/predicted_path.hpp"

namespace vimg {

struct LiveTrackerOptions {
  double velocity_time_constant_s = 0.02;
  double min_interval_s = 0.001;
  double max_extrapolation_s = 0.03;
  double stale_after_s = 0.1;
  // With prediction: the span over which the predicted offset is interpolated (0: every step).
  double prediction_interval_s = kDefaultPredictionInterval_s;
};

class LiveTracker {
 public:
  static constexpr int kMaxFingers = kMaxLiveFingers;

  explicit LiveTracker(const LiveTrackerOptions& options = {}) : options_(options) {}

  // Applies one event at render time now_s. False if dropped (stale, or finger out of range).
  bool apply(const TouchEvent& event, double now_s);

  // The fingers in contact during the step ending at time_s; returns how many were written.
  std::size_t steps_at(double time_s, double dt_s, std::span<FingerStep, kMaxFingers> out);

  std::uint64_t dropped_events() const { return dropped_; }

  // Predict each finger horizon_s ahead of the step time with `model`; horizon_s <= 0 (or not
  // finite) turns prediction off. Call before the first step or between steps, never during one.
  void set_prediction(double horizon_s, TouchPredictionModel model = kDefaultTouchPredictionModel);
  double prediction_horizon_s() const { return horizon_s_; }
  // How many times the predictor's model has run, all fingers, since construction.
  std::uint64_t model_runs() const { return model_runs_; }

 private:
  struct Finger {
    bool down = false;
    bool lifted_pending = false;  // lifted since the last step: report its final step once
    std::uint32_t touch_id = 0;
    double event_time_s = 0.0;    // last event
    double event_x_m = 0.0;
    double event_y_m = 0.0;
    double anchor_time_s = 0.0;   // the event that the next raw velocity is measured from
    double anchor_x_m = 0.0;
    double anchor_y_m = 0.0;
    double vx_m_per_s = 0.0;      // filtered
    double vy_m_per_s = 0.0;
    double pressure = 1.0;
    bool has_velocity = false;
    Vec3 rendered_m;              // position at the last step
    bool rendered_valid = false;
    FingerHistory history;        // mm, for the predictor
    PredictedPath path;           // the predictor's last runs on `history`
  };
  Vec3 reckoned_position(const Finger& f, double time_s) const;
  Vec3 position_at(Finger& f, double time_s);

  LiveTrackerOptions options_;
  std::array<Finger, kMaxFingers> fingers_{};
  std::uint32_t next_touch_id_ = 1;
  std::uint64_t dropped_ = 0;
  std::uint64_t model_runs_ = 0;
  double horizon_s_ = 0.0;
  TouchPredictionModel model_ = kDefaultTouchPredictionModel;
};

}  // namespace vimg
