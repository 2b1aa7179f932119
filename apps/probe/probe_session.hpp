#pragma once
// The virtual probe's rendering, without SDL: the mouse sets where the probe should be; the
// session moves it there in straight steps at the render rate (so a jump of the mouse becomes a
// fast stroke, not a teleport), evaluates the scene each step, and keeps the latest forces and
// the vibrotactile samples for audio.
#include <memory>
#include <vector>

#include "player/haptic/haptic_scene.hpp"

namespace vimg::probe {

struct ProbeForces {
  Vec3 position_m;
  Vec3 kinaesthetic_N;
  Vec3 vibrotactile_N;
  Vec3 total_N;  // clamped once to the device limit
};

class ProbeSession {
 public:
  ProbeSession(std::unique_ptr<HapticScene> scene, double rate_hz, double max_force_N, Vec3 start_m);

  // Renders `duration_s` of time while the probe moves linearly from where it is to target_m.
  // Appends one vibrotactile sample per step (the component along `audio_axis`, in N) to audio.
  void advance(double duration_s, const Vec3& target_m, const Vec3& audio_axis, std::vector<float>& audio);

  const ProbeForces& latest() const { return latest_; }
  double time_s() const { return time_s_; }
  double rate_hz() const { return rate_hz_; }

 private:
  std::unique_ptr<HapticScene> scene_;
  double rate_hz_;
  double max_force_N_;
  double time_s_ = 0.0;
  double carry_s_ = 0.0;
  InteractionState state_;
  ProbeForces latest_;
};

}  // namespace vimg::probe
