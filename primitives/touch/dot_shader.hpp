#pragma once
// DOT (DESIGN section 4): while the finger is within the disc, a carrier at the actuator resonance
// with amplitude gain * f_N(I), I = m * v_entry, f_N(I) = min(1, I / (m * fullSpeed)), phase zero
// at the exact entry time alpha. Zero outside. Every new crossing fires again.
#include "primitives/geometry/box2.hpp"
#include "primitives/geometry/shapes.hpp"
#include "primitives/image.hpp"
#include "primitives/shader.hpp"
#include "primitives/touch/touch_context.hpp"

namespace vimg {

class DotShader final : public ForceShader {
 public:
  DotShader(const Dot& dot, const TouchContext& context);

  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

  Box2 bounding_box_m() const { return bounding_box(disc_); }
  const Disc& disc_m() const { return disc_; }

 private:
  Disc disc_;
  double gain_;
  TouchContext context_;
};

}  // namespace vimg
