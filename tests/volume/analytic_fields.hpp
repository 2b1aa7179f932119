#pragma once
// Analytic volumes for checking shaders against their equations.
#include "primitives/volume/volume_field.hpp"

namespace vimg::testing {

// Lambda(x) = a . x + b
class LinearScalar final : public ScalarVolume {
 public:
  LinearScalar(Vec3 a, double b) : a_(a), b_(b) {}
  double value(const Vec3& p) const override { return dot(a_, p) + b_; }
  Vec3 gradient_per_m(const Vec3&) const override { return a_; }

 private:
  Vec3 a_;
  double b_;
};

// Lambda(x) = c |x|^2, gradient 2 c x
class QuadraticScalar final : public ScalarVolume {
 public:
  explicit QuadraticScalar(double c) : c_(c) {}
  double value(const Vec3& p) const override { return c_ * dot(p, p); }
  Vec3 gradient_per_m(const Vec3& p) const override { return 2.0 * c_ * p; }

 private:
  double c_;
};

class UniformVector final : public VectorVolume {
 public:
  explicit UniformVector(Vec3 v) : v_(v) {}
  Vec3 vector(const Vec3&) const override { return v_; }

 private:
  Vec3 v_;
};

}  // namespace vimg::testing
