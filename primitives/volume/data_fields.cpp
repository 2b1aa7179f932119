#include "primitives/volume/data_fields.hpp"

#include <numbers>

namespace vimg {

double MappedSpatialFrequency::omega_rad_per_m(const Vec3& position_m) const {
  const double mapped = transfer_(volume_->value(position_m));
  if (output_ == Output::omega_rad_per_m) return mapped;
  return mapped > 0.0 ? 2.0 * std::numbers::pi / mapped : 0.0;  // a zero period renders nothing
}

}  // namespace vimg
