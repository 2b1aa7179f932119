#pragma once
// The one limiter applied to a summed drive. Identity for |d| <= kSoftLimitKnee, so a single
// primitive keeps its exact shape; above the knee the excess is compressed with tanh, which keeps
// value and slope continuous at the knee and approaches 1 without reaching it:
//   y = sign(d) * (k + (1 - k) * tanh((|d| - k) / (1 - k))),  k = 0.5.
// NaN becomes 0, so no output ever leaves [-1, 1].
//
// Threads: a pure function; safe anywhere, including real-time threads.
#include <cmath>

namespace vimg {

inline constexpr double kSoftLimitKnee = 0.5;

inline double soft_limit(double d) noexcept {
  if (std::isnan(d)) return 0.0;
  const double a = std::fabs(d);
  if (a <= kSoftLimitKnee) return d;
  const double span = 1.0 - kSoftLimitKnee;
  const double y = kSoftLimitKnee + span * std::tanh((a - kSoftLimitKnee) / span);
  return d < 0.0 ? -y : y;
}

}  // namespace vimg
