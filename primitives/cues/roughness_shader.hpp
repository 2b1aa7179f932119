#pragma once
// Roughness (volume paper, eqs 4-5): f = q A s(v) sin(alpha), alpha += omega(x) |x(t) - x(t - dt)|.
// The phase follows the distance travelled, so a still probe renders a constant phase and, with
// s(v) = min(1, v / full_amplitude_speed), no force at all.
#include <memory>

#include "primitives/cues/spatial_frequency_field.hpp"
#include "primitives/shader.hpp"

namespace vimg {

struct RoughnessParams {
  Vec3 direction{0, 0, 1};                  // q, unit vector
  double amplitude_N = 0.6;                 // A at full speed
  double full_amplitude_speed_m_per_s = 0.03;  // amplitude rises linearly up to this speed
};

class RoughnessShader final : public ForceShader {
 public:
  RoughnessShader(std::shared_ptr<const SpatialFrequencyField> field, const RoughnessParams& params);

  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  // A field covers all of space: the contact lasts as long as the caller keeps it.
  bool active(const ShaderState& state) const override;

 private:
  std::shared_ptr<const SpatialFrequencyField> field_;
  RoughnessParams params_;
};

}  // namespace vimg
