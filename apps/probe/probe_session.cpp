#include "apps/probe/probe_session.hpp"

#include <cmath>

#include "primitives/force_sum.hpp"

namespace vimg::probe {

ProbeSession::ProbeSession(std::unique_ptr<HapticScene> scene, double rate_hz, double max_force_N, Vec3 start_m)
    : scene_(std::move(scene)), rate_hz_(rate_hz), max_force_N_(max_force_N) {
  state_.position_m = start_m;
  state_.previous_position_m = start_m;
  latest_.position_m = start_m;
  scene_->begin_contact();
}

void ProbeSession::advance(double duration_s, const Vec3& target_m, const Vec3& audio_axis, std::vector<float>& audio) {
  carry_s_ += duration_s;
  const double dt = 1.0 / rate_hz_;
  const auto steps = static_cast<int>(std::floor(carry_s_ * rate_hz_));
  if (steps <= 0) return;
  carry_s_ -= steps * dt;
  const Vec3 start = state_.position_m;
  const Vec3 velocity = (target_m - start) / (steps * dt);
  for (int n = 1; n <= steps; ++n) {
    time_s_ += dt;
    state_.previous_position_m = state_.position_m;
    state_.position_m = start + (target_m - start) * (static_cast<double>(n) / steps);
    state_.velocity_m_per_s = velocity;
    state_.proxy_position_m = state_.position_m;
    state_.proxy_velocity_m_per_s = velocity;
    state_.dt_s = dt;
    state_.time_s = time_s_;
    const FeedbackParts parts = scene_->evaluate(state_);
    ForceSum sum;
    sum.add(parts.kinaesthetic_N);
    sum.add(parts.vibrotactile_N);
    latest_ = {state_.position_m, parts.kinaesthetic_N, parts.vibrotactile_N, sum.clamped_N(max_force_N_)};
    audio.push_back(static_cast<float>(dot(parts.vibrotactile_N, audio_axis)));
  }
}

}  // namespace vimg::probe
