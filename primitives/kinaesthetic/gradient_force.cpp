#include "primitives/kinaesthetic/gradient_force.hpp"

namespace vimg {

void GradientForceShader::begin_contact(ShaderState&) const {}

Vec3 GradientForceShader::force_N(const InteractionState& interaction, ShaderState&) const {
  return scale_N_m_ * field_.gradient_per_m(interaction.position_m);
}

bool GradientForceShader::active(const ShaderState&) const { return true; }

}  // namespace vimg
