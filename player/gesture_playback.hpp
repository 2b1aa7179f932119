#pragma once
// Plays a gesture as exact finger steps: positions are linear in time between rows, so the
// velocity of a step is the velocity of the gesture segment it lies on (no filtering needed).
#include <cstddef>
#include <vector>

#include "player/finger_step.hpp"
#include "primitives/gesture.hpp"

namespace vimg {

class GesturePlayback {
 public:
  explicit GesturePlayback(const Gesture& gesture);

  // The fingers in contact during the step (time_s - dt_s, time_s]. Times must not decrease
  // between calls. A touch that starts inside the step starts at its down point; one that lifts
  // inside the step ends at its lift point and is reported for that step.
  void steps_at(double time_s, double dt_s, std::vector<FingerStep>& out);

  double start_time_s() const { return start_time_s_; }
  double end_time_s() const { return end_time_s_; }
  std::size_t max_simultaneous_touches() const;

 private:
  struct Track {
    int finger;
    std::vector<GesturePoint> points;
  };
  static Vec3 position_at(const Track& track, double time_s);
  static Vec3 velocity_at(const Track& track, double time_s);
  std::vector<Track> tracks_;
  double start_time_s_ = 0.0;
  double end_time_s_ = 0.0;
};

}  // namespace vimg
