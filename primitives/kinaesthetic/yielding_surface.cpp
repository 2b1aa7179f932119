#include "primitives/kinaesthetic/yielding_surface.hpp"

#include "primitives/kinaesthetic/proxy_state.hpp"

namespace vimg {

void YieldingSurfaceShader::begin_contact(ShaderState& state) const { state.emplace<ProxyState>(); }

Vec3 YieldingSurfaceShader::force_N(const InteractionState& interaction, ShaderState& state) const {
  const Vec3 probe = interaction.position_m;
  ProxyState& s = proxy_placed_at(state, probe);
  const Vec3 old_proxy = s.proxy_m;
  const double k = params_.coupling.stiffness_N_per_m;
  const Vec3 gradient = field_.gradient_per_m(s.proxy_m);
  const double gradient_norm = norm(gradient);
  if (!(k > 0.0) || gradient_norm <= 0.0 || gradient_norm < params_.min_gradient_per_m) {
    s.proxy_m = probe;
  } else {
    const Vec3 n = gradient / gradient_norm;
    const Vec3 d = probe - s.proxy_m;
    double d_n = dot(d, n);
    const Vec3 d_t = d - d_n * n;
    // Across the surface: yield above the yield force.
    const double max_d_n = params_.yield_force_N / k;
    if (std::abs(d_n) > max_d_n) {
      const double give = std::abs(d_n) - max_d_n;
      s.proxy_m += (d_n > 0.0 ? give : -give) * n;
      d_n = d_n > 0.0 ? max_d_n : -max_d_n;
    }
    // Along the surface: stick within the friction cone, otherwise slide to its edge.
    const double max_d_t = params_.friction * std::abs(d_n);
    const double t = norm(d_t);
    if (t > max_d_t) s.proxy_m += d_t * ((t - max_d_t) / t);
  }
  s.proxy_velocity_m_per_s = interaction.dt_s > 0.0 ? (s.proxy_m - old_proxy) / interaction.dt_s : Vec3{};
  return virtual_coupling_force_N(params_.coupling, probe, interaction.velocity_m_per_s, s.proxy_m,
                                  s.proxy_velocity_m_per_s);
}

bool YieldingSurfaceShader::active(const ShaderState&) const { return true; }

}  // namespace vimg
