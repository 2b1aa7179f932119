#include "player/live_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

namespace {
constexpr double kMetresPerMm = 1e-3;
}

bool LiveTracker::apply(const TouchEvent& e, double now_s) {
  if (e.finger < 0 || e.finger >= kMaxFingers || !std::isfinite(e.x_mm) || !std::isfinite(e.y_mm) ||
      !std::isfinite(e.time_s)) {
    ++dropped_;
    return false;
  }
  if (e.phase != TouchPhase::up && now_s - e.time_s > options_.stale_after_s) {
    ++dropped_;  // a late vibration is worse than none
    return false;
  }
  Finger& f = fingers_[static_cast<std::size_t>(e.finger)];
  const double x = e.x_mm * kMetresPerMm;
  const double y = e.y_mm * kMetresPerMm;
  const double pressure = std::isfinite(e.pressure) ? std::clamp(e.pressure, 0.0, 1.0) : 1.0;
  if (e.phase == TouchPhase::down || !f.down) {
    if (e.phase == TouchPhase::up) {
      ++dropped_;  // an up for a finger that is not down
      return false;
    }
    f = Finger{};
    f.down = true;
    f.touch_id = next_touch_id_++;
    f.event_time_s = e.time_s;
    f.event_x_m = x;
    f.event_y_m = y;
    f.anchor_time_s = e.time_s;
    f.anchor_x_m = x;
    f.anchor_y_m = y;
    f.pressure = pressure;
    reset_finger_history(f.history);
    add_finger_event(f.history, e.time_s, e.x_mm, e.y_mm);
    reset_predicted_path(f.path);
    return true;
  }
  f.pressure = pressure;
  if (e.phase == TouchPhase::up) {
    f.down = false;
    f.lifted_pending = true;
    f.event_x_m = x;
    f.event_y_m = y;
    f.event_time_s = std::max(f.event_time_s, e.time_s);
    return true;
  }
  f.event_time_s = std::max(f.event_time_s, e.time_s);
  f.event_x_m = x;
  f.event_y_m = y;
  add_finger_event(f.history, e.time_s, e.x_mm, e.y_mm);
  reset_predicted_path(f.path);
  const double dt = e.time_s - f.anchor_time_s;
  if (dt < options_.min_interval_s) return true;  // too close for a usable velocity: position only
  const double raw_vx = (x - f.anchor_x_m) / dt;
  const double raw_vy = (y - f.anchor_y_m) / dt;
  if (!f.has_velocity) {
    f.vx_m_per_s = raw_vx;
    f.vy_m_per_s = raw_vy;
    f.has_velocity = true;
  } else {
    const double a = 1.0 - std::exp(-dt / options_.velocity_time_constant_s);
    f.vx_m_per_s += a * (raw_vx - f.vx_m_per_s);
    f.vy_m_per_s += a * (raw_vy - f.vy_m_per_s);
  }
  f.anchor_time_s = e.time_s;
  f.anchor_x_m = x;
  f.anchor_y_m = y;
  return true;
}

Vec3 LiveTracker::reckoned_position(const Finger& f, double time_s) const {
  const double ahead = std::clamp(time_s - f.event_time_s, 0.0, options_.max_extrapolation_s);
  return {f.event_x_m + f.vx_m_per_s * ahead, f.event_y_m + f.vy_m_per_s * ahead, 0.0};
}

void LiveTracker::set_prediction(double horizon_s, TouchPredictionModel model) {
  horizon_s_ = std::isfinite(horizon_s) && horizon_s > 0.0 ? horizon_s : 0.0;
  model_ = model;
}

Vec3 LiveTracker::position_at(Finger& f, double time_s) {
  if (horizon_s_ <= 0.0) return reckoned_position(f, time_s);
  const int runs = f.path.predictions;
  const PredictedPosition p = predicted_path_at(f.path, f.history, std::max(time_s, f.event_time_s), horizon_s_, model_,
                                                options_.prediction_interval_s);
  model_runs_ += static_cast<std::uint64_t>(f.path.predictions - runs);
  return {p.x_mm * kMetresPerMm, p.y_mm * kMetresPerMm, 0.0};
}

std::size_t LiveTracker::steps_at(double time_s, double, std::span<FingerStep, kMaxFingers> out) {
  std::size_t n = 0;
  for (int i = 0; i < kMaxFingers; ++i) {
    Finger& f = fingers_[static_cast<std::size_t>(i)];
    if (!f.down && !f.lifted_pending) continue;
    FingerStep& s = out[n++];
    s.finger = i;
    s.touch_id = f.touch_id;
    const Vec3 lifted_at = horizon_s_ > 0.0 && f.rendered_valid ? f.rendered_m : Vec3{f.event_x_m, f.event_y_m, 0.0};
    s.position_m = f.down ? position_at(f, time_s) : lifted_at;
    s.previous_position_m = f.rendered_valid ? f.rendered_m : s.position_m;
    // Velocity is reported only while the events are fresh enough to trust it.
    // With prediction, as long as the predictor still follows the finger (until the silence fade ends).
    const double fresh_for_s = horizon_s_ > 0.0 ? kSilenceStop_s : options_.max_extrapolation_s;
    const bool fresh = f.down && time_s - f.event_time_s <= fresh_for_s;
    s.velocity_m_per_s = fresh ? Vec3{f.vx_m_per_s, f.vy_m_per_s, 0.0} : Vec3{};
    s.pressure = f.pressure;
    f.rendered_m = s.position_m;
    f.rendered_valid = true;
    f.lifted_pending = false;
  }
  return n;
}

}  // namespace vimg
