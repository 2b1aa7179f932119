#pragma once
// A proxy-based yielding surface along the gradient of a scalar volume (constraint-based volume
// haptics). Where |grad| is at least min_gradient_per_m the surface normal is n = grad/|grad| at
// the proxy. Each step, with d = x_probe - x_proxy split into d_n = (d.n) n and d_t = d - d_n:
//   - across the surface the proxy stays put while k_s |d_n| <= yield_force_N, and otherwise
//     gives way along n until k_s |d_n| = yield_force_N (the surface is penetrated);
//   - along the surface, Coulomb friction: the proxy stays while k_s |d_t| <= mu k_s |d_n|, and
//     otherwise slides until k_s |d_t| = mu k_s |d_n|.
// Where the gradient is weaker the proxy follows the probe (free space). The output is the
// virtual coupling force (eq 3) between the probe and the moved proxy.
#include "primitives/kinaesthetic/virtual_coupling.hpp"
#include "primitives/volume/volume_field.hpp"

namespace vimg {

struct YieldingSurfaceParams {
  CouplingParams coupling;
  double yield_force_N = 1.5;       // force needed to push through the surface
  double friction = 0.3;            // mu: tangential force / normal force while sticking
  double min_gradient_per_m = 0.0;  // weaker gradients are free space
};

class YieldingSurfaceShader final : public ForceShader {
 public:
  YieldingSurfaceShader(const ScalarVolume& field, YieldingSurfaceParams params) : field_(field), params_(params) {}
  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

 private:
  const ScalarVolume& field_;
  YieldingSurfaceParams params_;
};

}  // namespace vimg
