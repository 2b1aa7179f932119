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
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "player/finger_step.hpp"
#include "player/touch_event.hpp"

namespace vimg {

struct LiveTrackerOptions {
  double velocity_time_constant_s = 0.02;
  double min_interval_s = 0.001;
  double max_extrapolation_s = 0.03;
  double stale_after_s = 0.1;
};

class LiveTracker {
 public:
  static constexpr int kMaxFingers = 10;

  explicit LiveTracker(const LiveTrackerOptions& options = {}) : options_(options) {}

  // Applies one event at render time now_s. False if dropped (stale, or finger out of range).
  bool apply(const TouchEvent& event, double now_s);

  // The fingers in contact during the step ending at time_s; returns how many were written.
  std::size_t steps_at(double time_s, double dt_s, std::span<FingerStep, kMaxFingers> out);

  std::uint64_t dropped_events() const { return dropped_; }

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
  };
  Vec3 reckoned_position(const Finger& f, double time_s) const;

  LiveTrackerOptions options_;
  std::array<Finger, kMaxFingers> fingers_{};
  std::uint32_t next_touch_id_ = 1;
  std::uint64_t dropped_ = 0;
};

}  // namespace vimg
