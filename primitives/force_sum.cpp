#include "primitives/force_sum.hpp"

namespace vimg {

Vec3 clamp_magnitude(const Vec3& force_N, double max_force_N) {
  if (!(max_force_N > 0.0)) return Vec3{};
  const double magnitude = norm(force_N);
  if (magnitude <= max_force_N) return force_N;
  return force_N * (max_force_N / magnitude);
}

}  // namespace vimg
