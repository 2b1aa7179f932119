#include "player/haptic/haptic_cycle.hpp"

#include <algorithm>

#include "primitives/force_sum.hpp"

namespace vimg {

void HapticCycle::set_scene(HapticScene* scene, double time_s) {
  if (previous_ && !retired_) retired_ = previous_;
  previous_ = current_;
  current_ = scene;
  if (current_) current_->begin_contact();
  fade_start_s_ = time_s;
}

HapticScene* HapticCycle::take_retired() {
  HapticScene* r = retired_;
  retired_ = nullptr;
  return r;
}

CycleOutput HapticCycle::step(const ProbeSample& probe, double time_s) {
  InteractionState s;
  s.position_m = probe.position_m;
  s.velocity_m_per_s = probe.velocity_m_per_s;
  s.previous_position_m = have_last_ ? last_position_m_ : probe.position_m;
  s.time_s = time_s;
  s.dt_s = have_last_ ? std::max(0.0, time_s - last_time_s_) : 0.0;
  // The proxy shaders keep their own proxies; an external proxy defaults to the probe itself.
  s.proxy_position_m = probe.position_m;
  s.proxy_velocity_m_per_s = probe.velocity_m_per_s;
  have_last_ = true;
  last_position_m_ = probe.position_m;
  last_time_s_ = time_s;

  CycleOutput out;
  Vec3 current_total;
  if (current_) {
    out.parts = current_->evaluate(s);
    current_total = out.parts.total_N();
  }
  ForceSum sum;
  if (previous_) {
    const double w = config_.crossfade_time_s > 0.0
                         ? std::clamp((time_s - fade_start_s_) / config_.crossfade_time_s, 0.0, 1.0)
                         : 1.0;
    const Vec3 old_total = previous_->evaluate(s).total_N();
    sum.add((1.0 - w) * old_total);
    sum.add(w * current_total);
    if (w >= 1.0 && !retired_) {
      retired_ = previous_;
      previous_ = nullptr;
    }
  } else {
    sum.add(current_total);
  }
  out.total_N = sum.unclamped_N();
  return out;
}

}  // namespace vimg
