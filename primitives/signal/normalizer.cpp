#include "primitives/signal/normalizer.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

double hard_clamp(double drive) {
  if (std::isnan(drive)) return 0.0;
  return std::clamp(drive, -1.0, 1.0);
}

double soft_limit(double drive, double knee) {
  if (std::isnan(drive)) return 0.0;
  knee = std::clamp(knee, 0.0, 1.0);
  const double magnitude = std::abs(drive);
  if (magnitude <= knee) return drive;
  if (knee >= 1.0) return std::copysign(1.0, drive);
  const double headroom = 1.0 - knee;
  const double limited = knee + headroom * std::tanh((magnitude - knee) / headroom);
  return std::copysign(std::min(limited, 1.0), drive);
}

Normalizer::Normalizer(const NormalizerParams& params)
    : axis_(normalized(params.axis)),
      inverse_full_scale_(params.full_scale_force_N > 0.0 ? 1.0 / params.full_scale_force_N : 0.0),
      limit_(params.limit),
      knee_(params.knee) {}

double Normalizer::raw_drive(const Vec3& force_N) const { return dot(force_N, axis_) * inverse_full_scale_; }

double Normalizer::drive(const Vec3& force_N) const {
  const double raw = raw_drive(force_N);
  return limit_ == LimitMode::soft_knee ? soft_limit(raw, knee_) : hard_clamp(raw);
}

}  // namespace vimg
