#pragma once
// Force -> normalized drive for a single-axis actuator: the component of the summed force along
// the actuator axis, divided by the actuator's full-scale force, then limited to [-1, 1] either
// by a hard clamp or by a soft limiter that is linear below a knee and saturates smoothly above.
#include "primitives/vec3.hpp"

namespace vimg {

enum class LimitMode { hard_clamp, soft_knee };

// Clamp to [-1, 1]; NaN becomes 0.
double hard_clamp(double drive);
// Identity for |x| <= knee; above it knee + (1 - knee) tanh((|x| - knee) / (1 - knee)), which
// keeps slope 1 at the knee and approaches 1 without reaching it. knee is clamped to [0, 1];
// knee 1 is the hard clamp. NaN becomes 0.
double soft_limit(double drive, double knee);

struct NormalizerParams {
  Vec3 axis{0, 0, 1};           // unit vector of the actuator's motion
  double full_scale_force_N = 1.0;
  LimitMode limit = LimitMode::hard_clamp;
  double knee = 0.8;            // soft_knee only
};

class Normalizer {
 public:
  explicit Normalizer(const NormalizerParams& params);
  // Unlimited ratio (may exceed 1): useful to see how far a scene overdrives.
  double raw_drive(const Vec3& force_N) const;
  // In [-1, 1].
  double drive(const Vec3& force_N) const;

 private:
  Vec3 axis_;
  double inverse_full_scale_;
  LimitMode limit_;
  double knee_;
};

}  // namespace vimg
