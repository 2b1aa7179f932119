#pragma once
// A desktop force-feedback device: the probe's position and velocity, its buttons, a force to
// render, and the limits the device can render safely. The haptic loop drives it through the
// HapticPort it extends.
#include "player/haptic/haptic_port.hpp"

namespace vimg {

struct ForceDeviceLimits {
  double max_force_N = 3.3;              // Fmax
  double max_stiffness_N_per_m = 400.0;  // Kmax
  Vec3 workspace_m{0.16, 0.12, 0.12};    // full extents, centred on the origin
};

class ForceDevice : public HapticPort {
 public:
  virtual ForceDeviceLimits limits() const = 0;
  double max_force_N() const override { return limits().max_force_N; }
};

}  // namespace vimg
