#pragma once
// Vector-field guidance with anisotropic resistance (constraint-based volume haptics). With
// t = V/|V| at the proxy and d = x_probe - x_proxy:
//   - along the field the proxy follows the probe freely: it moves by (d.t) t;
//   - across the field the proxy stays while k_s |d_perp| <= across_force_N, and otherwise is
//     dragged until k_s |d_perp| = across_force_N, so leaving a stream line takes that force;
//   - optionally, a flow-following pull of follow_force_N along t.
// Where |V| < min_magnitude the proxy follows the probe. The output is the virtual coupling
// force (eq 3) plus the pull.
#include "primitives/kinaesthetic/virtual_coupling.hpp"
#include "primitives/volume/volume_field.hpp"

namespace vimg {

struct VectorGuidanceParams {
  CouplingParams coupling;
  double across_force_N = 1.5;  // resistance to motion across the field
  double follow_force_N = 0.0;  // pull along the field (0: guidance only)
  double min_magnitude = 1e-6;  // weaker vectors are free space
};

class VectorGuidanceShader final : public ForceShader {
 public:
  VectorGuidanceShader(const VectorVolume& field, VectorGuidanceParams params) : field_(field), params_(params) {}
  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

 private:
  const VectorVolume& field_;
  VectorGuidanceParams params_;
};

}  // namespace vimg
