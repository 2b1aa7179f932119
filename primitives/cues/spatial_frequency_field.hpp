#pragma once
// The spatial angular frequency omega (rad/m) of the roughness texture at a point (volume paper,
// eq 5). The volume backend derives it from the data; ConstantSpatialFrequency is the simplest.
#include "primitives/vec3.hpp"

namespace vimg {

class SpatialFrequencyField {
 public:
  virtual ~SpatialFrequencyField() = default;
  virtual double omega_rad_per_m(const Vec3& position_m) const = 0;
};

class ConstantSpatialFrequency final : public SpatialFrequencyField {
 public:
  explicit ConstantSpatialFrequency(double omega_rad_per_m) : omega_rad_per_m_(omega_rad_per_m) {}
  double omega_rad_per_m(const Vec3&) const override { return omega_rad_per_m_; }

 private:
  double omega_rad_per_m_;
};

}  // namespace vimg
