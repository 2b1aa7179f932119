#pragma once
// What a shader sees of one interaction point (a finger on a touchscreen, or the probe of a
// force device) at one evaluation time. All quantities are SI.
#include "primitives/vec3.hpp"

namespace vimg {

struct InteractionState {
  Vec3 position_m;           // at time_s
  Vec3 previous_position_m;  // at time_s - dt_s: shaders locate events inside the step with it
  Vec3 velocity_m_per_s;     // filtered estimate at time_s
  double time_s = 0.0;
  double dt_s = 0.0;         // the step since the previous evaluation of this contact
  double pressure = 1.0;     // normalized [0, 1]; 1 when the device does not report pressure
  int tool_id = 0;           // finger index on a touchscreen, tool index on a force device
  // Kinaesthetic rendering only: the proxy that the probe is coupled to.
  Vec3 proxy_position_m;
  Vec3 proxy_velocity_m_per_s;
};

}  // namespace vimg
