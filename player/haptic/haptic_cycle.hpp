#pragma once
// Rendering of one haptic cycle, without threads or clocks (the loop supplies time): evaluate the
// current scene (and the previous one while cross-fading) at the probe, and sum.
// Scene changes cross-fade linearly over crossfade_time_s: (1 - w) F_old + w F_new.
// Everything that keeps the force safe (start-up gate, soft wall, the one clamp, slew limit,
// watchdogs) is the SafetyStack's, which the loop applies to this cycle's total.
//
// Threads: one thread at a time (the loop thread); step() neither allocates, locks nor throws.
#include "player/haptic/haptic_port.hpp"
#include "player/haptic/haptic_scene.hpp"

namespace vimg {

struct HapticCycleConfig {
  double crossfade_time_s = 0.1;
};

struct CycleOutput {
  FeedbackParts parts;  // of the current scene, before fading
  Vec3 total_N;         // cross-faded sum of both parts, not yet clamped
};

class HapticCycle {
 public:
  explicit HapticCycle(HapticCycleConfig config = {}) : config_(config) {}

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
  bool have_last_ = false;
  Vec3 last_position_m_;
  double last_time_s_ = 0.0;
};

}  // namespace vimg
