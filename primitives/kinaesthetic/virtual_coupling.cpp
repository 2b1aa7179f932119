#include "primitives/kinaesthetic/virtual_coupling.hpp"

namespace vimg {

Vec3 virtual_coupling_force_N(const CouplingParams& coupling, const Vec3& probe_m,
                              const Vec3& probe_velocity_m_per_s, const Vec3& proxy_m,
                              const Vec3& proxy_velocity_m_per_s) {
  return -coupling.stiffness_N_per_m * (probe_m - proxy_m) -
         coupling.damping_N_s_per_m * (probe_velocity_m_per_s - proxy_velocity_m_per_s);
}

void VirtualCouplingShader::begin_contact(ShaderState&) const {}

Vec3 VirtualCouplingShader::force_N(const InteractionState& interaction, ShaderState&) const {
  return virtual_coupling_force_N(coupling_, interaction.position_m, interaction.velocity_m_per_s,
                                  interaction.proxy_position_m, interaction.proxy_velocity_m_per_s);
}

bool VirtualCouplingShader::active(const ShaderState&) const { return true; }

}  // namespace vimg
