#pragma once
// One cycle of kinaesthetic rendering, without threads or clocks (the loop supplies time):
//   1. evaluate the current scene (and the previous one while cross-fading) at the probe;
//   2. sum kinaesthetic and vibrotactile parts and clamp once to the force limit;
//   3. gate start-up: send nothing until the computed force is below gate_force_N, then ramp
//      the output in linearly over ramp_time_s.
// Scene changes cross-fade linearly over crossfade_time_s: (1 - w) F_old + w F_new.
#include "player/haptic/haptic_port.hpp"
#include "player/haptic/haptic_scene.hpp"

namespace vimg {

struct HapticCycleConfig {
  double max_force_N = 3.3;  // the device limit (the smaller of device and scene profile)
  double gate_force_N = 0.2;
  double ramp_time_s = 0.5;
  double crossfade_time_s = 0.1;
};

struct CycleOutput {
  FeedbackParts parts;  // of the current scene, before fading, gating and clamping
  Vec3 total_N;         // cross-faded sum, clamped once
  Vec3 sent_N;          // after start-up gating: what goes to the device
  bool gated = true;    // still waiting for a small force
};

class HapticCycle {
 public:
  explicit HapticCycle(HapticCycleConfig config) : config_(config) {}

  // Starts rendering `scene` at time_s, cross-fading from the current one (if any). The caller
  // keeps both alive until fading() is false. The scene's contact restarts.
  void set_scene(HapticScene* scene, double time_s);
  bool fading() const { return previous_ != nullptr; }
  HapticScene* current() const { return current_; }
  // The scene that faded out and may now be released (nullptr if none); clears it.
  HapticScene* take_retired();

  CycleOutput step(const ProbeSample& probe, double time_s);

 private:
  HapticCycleConfig config_;
  HapticScene* current_ = nullptr;
  HapticScene* previous_ = nullptr;
  HapticScene* retired_ = nullptr;
  double fade_start_s_ = 0.0;
  bool gated_ = true;
  double ramp_start_s_ = 0.0;
  bool have_last_ = false;
  Vec3 last_position_m_;
  double last_time_s_ = 0.0;
};

}  // namespace vimg
