#pragma once
// A scalar field over space (SI positions), such as a volume's density. The transition cue fires
// when the probe crosses one of its iso-values. The volume backend implements it over grids.
#include "primitives/vec3.hpp"

namespace vimg {

class ScalarField {
 public:
  virtual ~ScalarField() = default;
  virtual double value(const Vec3& position_m) const = 0;
};

}  // namespace vimg
