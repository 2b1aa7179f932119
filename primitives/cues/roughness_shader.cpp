#include "primitives/cues/roughness_shader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace vimg {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct RoughnessState {
  double phase_rad;  // alpha, kept in [0, 2 pi)
};

}  // namespace

RoughnessShader::RoughnessShader(std::shared_ptr<const SpatialFrequencyField> field, const RoughnessParams& params)
    : field_(std::move(field)), params_(params) {}

void RoughnessShader::begin_contact(ShaderState& state) const { state.emplace<RoughnessState>(); }

Vec3 RoughnessShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  auto& s = state.get<RoughnessState>();
  if (!field_) return Vec3{};
  const double travelled_m = norm(interaction.position_m - interaction.previous_position_m);
  const double omega = field_->omega_rad_per_m(interaction.position_m);
  s.phase_rad = std::fmod(s.phase_rad + omega * travelled_m, kTwoPi);
  if (s.phase_rad < 0.0) s.phase_rad += kTwoPi;
  const double speed = norm(interaction.velocity_m_per_s);
  const double ramp = params_.full_amplitude_speed_m_per_s > 0.0
                          ? std::min(1.0, speed / params_.full_amplitude_speed_m_per_s)
                          : 1.0;
  return params_.direction * (params_.amplitude_N * ramp * std::sin(s.phase_rad));
}

bool RoughnessShader::active(const ShaderState&) const { return true; }

}  // namespace vimg
