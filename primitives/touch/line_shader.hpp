#pragma once
// LINE (DESIGN section 4): a plucked string. While the finger is in the band (a capsule of
// radius width/2 around the segment) a constant-amplitude carrier A0 * sin(omega_D (t - alpha)),
// A0 = gain * min(1, v_entry / fullSpeed); after the exit at beta the same phase continues under
// the envelope exp(-zeta omega_N (t - beta)) until it falls below -40 dB, then exactly 0.
#include "primitives/geometry/box2.hpp"
#include "primitives/geometry/shapes.hpp"
#include "primitives/image.hpp"
#include "primitives/shader.hpp"
#include "primitives/touch/touch_context.hpp"

namespace vimg {

// The ring-down ends when the envelope falls below this fraction of its start (-40 dB).
inline constexpr double kRingDownEndRatio = 0.01;

class LineShader final : public ForceShader {
 public:
  LineShader(const Line& line, const TouchContext& context);

  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  bool active(const ShaderState& state) const override;

  Box2 bounding_box_m() const { return bounding_box(band_); }
  const Capsule& band_m() const { return band_; }
  double omega_n_rad_per_s() const { return omega_n_; }
  double omega_d_rad_per_s() const { return omega_d_; }
  double damping_ratio() const { return zeta_; }

 private:
  Capsule band_;
  double omega_n_;
  double zeta_;
  double omega_d_;
  double ring_duration_s_;  // time from release until the envelope reaches -40 dB
  double gain_;
  TouchContext context_;
};

}  // namespace vimg
