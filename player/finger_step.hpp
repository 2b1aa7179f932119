#pragma once
// One finger in contact during one output step: where it was at the previous sample and where it
// is now. Produced by gesture playback (exact path) or by the live tracker (filtered events).
#include <cstdint>

#include "primitives/vec3.hpp"

namespace vimg {

struct FingerStep {
  int finger = 0;               // finger index (tool_id for the shaders)
  std::uint32_t touch_id = 0;   // distinguishes successive touches of the same finger
  Vec3 previous_position_m;     // at time_s - dt_s, or where the touch began within the step
  Vec3 position_m;              // at time_s
  Vec3 velocity_m_per_s;
  double pressure = 1.0;
};

}  // namespace vimg
