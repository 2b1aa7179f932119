#pragma once
// What every touch shader of one image shares: the interaction parameters in SI units, the
// actuator's carrier and full-scale force, and the orientation q along which it emits.
#include "primitives/image.hpp"
#include "primitives/vec3.hpp"

namespace vimg {

struct TouchContext {
  double mass_kg = 0.01;              // virtual mass m of the interaction point
  double full_speed_m_per_s = 0.1;    // speed at which drives reach full strength
  double max_deformation_m = 0.001;   // finger deformation at pressure 1
  double carrier_frequency_hz = 175.0;  // DOT carrier: the actuator's resonance
  double full_scale_force_N = 1.0;    // force that maps to a normalized drive of 1
  Vec3 axis{0, 0, 1};                 // orientation q of the vibrotactile force (unit vector)
};

// The document's interaction parameters (mm) in SI units (m).
TouchContext make_touch_context(const InteractionParams& params, double carrier_frequency_hz = 175.0);

}  // namespace vimg
