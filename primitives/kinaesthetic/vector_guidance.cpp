#include "primitives/kinaesthetic/vector_guidance.hpp"

#include "primitives/kinaesthetic/proxy_state.hpp"

namespace vimg {

void VectorGuidanceShader::begin_contact(ShaderState& state) const { state.emplace<ProxyState>(); }

Vec3 VectorGuidanceShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  const Vec3 probe = interaction.position_m;
  ProxyState& s = proxy_placed_at(state, probe);
  const Vec3 old_proxy = s.proxy_m;
  const double k = params_.coupling.stiffness_N_per_m;
  const Vec3 field = field_.vector(s.proxy_m);
  const double magnitude = norm(field);
  Vec3 pull;
  if (!(k > 0.0) || magnitude <= 0.0 || magnitude < params_.min_magnitude) {
    s.proxy_m = probe;
  } else {
    const Vec3 t = field / magnitude;
    const Vec3 d = probe - s.proxy_m;
    const Vec3 along = dot(d, t) * t;
    const Vec3 across = d - along;
    s.proxy_m += along;
    const double max_across = params_.across_force_N / k;
    const double a = norm(across);
    if (a > max_across) s.proxy_m += across * ((a - max_across) / a);
    pull = params_.follow_force_N * t;
  }
  s.proxy_velocity_m_per_s = interaction.dt_s > 0.0 ? (s.proxy_m - old_proxy) / interaction.dt_s : Vec3{};
  return virtual_coupling_force_N(params_.coupling, probe, interaction.velocity_m_per_s, s.proxy_m,
                                  s.proxy_velocity_m_per_s) +
         pull;
}

bool VectorGuidanceShader::active(const ShaderState&) const { return true; }

}  // namespace vimg
