#pragma once
// Scales another shader's force by a field: f = g(x_probe) * f_inner. With the roughness shader
// this makes its amplitude A a function of the data (volume paper, section 5: 0.6 N far from the
// feature, 0.3 N at it) without changing the roughness model. The inner shader's state is the
// contact's state, so this adds none.
#include <memory>

#include "primitives/cues/scalar_field.hpp"
#include "primitives/shader.hpp"

namespace vimg {

class ModulatedShader final : public ForceShader {
 public:
  ModulatedShader(std::shared_ptr<const ForceShader> inner, std::shared_ptr<const ScalarField> gain)
      : inner_(std::move(inner)), gain_(std::move(gain)) {}
  void begin_contact(ShaderState& state) const override { inner_->begin_contact(state); }
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override {
    return gain_->value(interaction.position_m) * inner_->force_N(interaction, state);
  }
  bool active(const ShaderState& state) const override { return inner_->active(state); }

 private:
  std::shared_ptr<const ForceShader> inner_;
  std::shared_ptr<const ScalarField> gain_;
};

}  // namespace vimg
