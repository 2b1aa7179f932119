#pragma once
// Small helpers shared by the touch shaders.
#include <algorithm>
#include <numbers>

#include "primitives/geometry/vec2.hpp"
#include "primitives/interaction_state.hpp"
#include "primitives/touch/touch_context.hpp"

namespace vimg::touch {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Speed in the screen plane (z ignored), m/s.
inline double planar_speed_m_per_s(const InteractionState& s) { return norm(xy(s.velocity_m_per_s)); }

// min(1, v / fullSpeed): the DOT's f_N(I) = I / (m fullSpeed) with I = m v (the mass cancels),
// the LINE's pluck strength, and the SURFACE's speed fade. A non-positive fullSpeed means full.
inline double full_speed_fraction(double speed_m_per_s, const TouchContext& context) {
  if (!(context.full_speed_m_per_s > 0.0)) return 1.0;
  return std::clamp(speed_m_per_s / context.full_speed_m_per_s, 0.0, 1.0);
}

// The force of a normalized drive along the actuator axis.
inline Vec3 drive_to_force_N(double drive, const TouchContext& context) {
  return context.axis * (drive * context.full_scale_force_N);
}

}  // namespace vimg::touch
