#pragma once
// What the kinaesthetic shaders read from volume data: a scalar property with its gradient and
// a vector property, both defined at every world point (SI units). Grids implement these by
// trilinear sampling; tests implement them with analytic functions.
#include "primitives/vec3.hpp"

namespace vimg {

class ScalarVolume {
 public:
  virtual ~ScalarVolume() = default;
  virtual double value(const Vec3& position_m) const = 0;
  // The spatial gradient, in data units per metre.
  virtual Vec3 gradient_per_m(const Vec3& position_m) const = 0;
};

class VectorVolume {
 public:
  virtual ~VectorVolume() = default;
  virtual Vec3 vector(const Vec3& position_m) const = 0;
};

}  // namespace vimg
