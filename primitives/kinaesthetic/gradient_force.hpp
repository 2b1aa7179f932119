#pragma once
// Gradient force function (volume paper, eq 2): f = C * grad(Lambda)(x_probe). A positive C pulls
// the probe towards high values, a negative C pushes it towards low values. Stateless.
#include "primitives/shader.hpp"
#include "primitives/volume/volume_field.hpp"

namespace vimg {

class GradientForceShader final : public ForceShader {
 public:
  // scale_N_m: C, in newtons per (data unit per metre). The field must outlive the shader.
  GradientForceShader(const ScalarVolume& field, double scale_N_m) : field_(field), scale_N_m_(scale_N_m) {}
  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

 private:
  const ScalarVolume& field_;
  double scale_N_m_;
};

}  // namespace vimg
