#include "primitives/touch/touch_context.hpp"

namespace vimg {

TouchContext make_touch_context(const InteractionParams& params, double carrier_frequency_hz) {
  TouchContext context;
  context.mass_kg = params.mass_kg;
  context.full_speed_m_per_s = params.full_speed_mm_per_s * 1e-3;
  context.max_deformation_m = params.max_deformation_mm * 1e-3;
  context.carrier_frequency_hz = carrier_frequency_hz;
  return context;
}

}  // namespace vimg
