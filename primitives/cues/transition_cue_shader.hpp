#pragma once
// Transition cue (volume paper, eq 6): when the probe crosses the iso-value of a scalar field,
// f = q A exp(-beta t') sin(omega_d t'), omega_d = sqrt(omega0^2 - beta^2), beta = 1 / tau,
// with t' measured from the exact crossing time, located between the two samples of the step by
// a bracketed root search on the field along the segment. The cue ends (exactly 0) when the
// envelope falls below -40 dB; a new crossing restarts it.
#include <memory>

#include "primitives/cues/scalar_field.hpp"
#include "primitives/shader.hpp"

namespace vimg {

struct TransitionCueParams {
  double iso_value = 0.0;
  Vec3 direction{0, 0, 1};  // q, unit vector
  double frequency_hz = 130.0;  // omega0 / 2 pi
  double amplitude_N = 0.3;
  double decay_time_s = 0.1;  // tau
  double position_tolerance_m = 1e-9;  // how exactly the crossing point is located
};

class TransitionCueShader final : public ForceShader {
 public:
  TransitionCueShader(std::shared_ptr<const ScalarField> field, const TransitionCueParams& params);

  void begin_contact(ShaderState& state) const override;
  Vec3 force_N(const InteractionState& interaction, ShaderState& state) const override;
  // A field covers all of space: the contact lasts as long as the caller keeps it.
  bool active(const ShaderState& state) const override;

  double omega_d_rad_per_s() const { return omega_d_; }
  double beta_per_s() const { return beta_; }
  // Where and when the last crossing of this contact happened (false if none yet).
  bool last_crossing(const ShaderState& state, Vec3& position_m, double& time_s) const;

 private:
  std::shared_ptr<const ScalarField> field_;
  TransitionCueParams params_;
  double beta_;
  double omega_d_;
  double duration_s_;  // until the envelope reaches -40 dB
};

}  // namespace vimg
