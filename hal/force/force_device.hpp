#pragma once
// A desktop force-feedback device: the probe's position and velocity, its buttons, a force to
// render, and the limits the device can render safely (ForceDeviceLimits, with HapticPort in
// player/haptic/haptic_port.hpp, since the loop's safety stack works from them). The haptic loop
// drives it through the HapticPort it is.
#include "player/haptic/haptic_port.hpp"

namespace vimg {

class ForceDevice : public HapticPort {};

}  // namespace vimg
