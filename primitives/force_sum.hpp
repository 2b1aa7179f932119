#pragma once
// Composition of shader outputs: sum every contribution, then clamp once (DESIGN section 3).
// Clamping scales the whole vector, so the direction of the summed force is kept.
#include "primitives/vec3.hpp"

namespace vimg {

Vec3 clamp_magnitude(const Vec3& force_N, double max_force_N);

class ForceSum {
 public:
  void add(const Vec3& force_N) { total_N_ += force_N; }
  const Vec3& unclamped_N() const { return total_N_; }
  Vec3 clamped_N(double max_force_N) const { return clamp_magnitude(total_N_, max_force_N); }

 private:
  Vec3 total_N_;
};

}  // namespace vimg
