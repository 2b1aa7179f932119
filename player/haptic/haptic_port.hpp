#pragma once
// What the haptic loop needs of a force device: read the probe, send a force. hal/force's
// ForceDevice extends this with limits and buttons; tests use the simulated device.
#include "primitives/vec3.hpp"

namespace vimg {

struct ProbeSample {
  Vec3 position_m;
  Vec3 velocity_m_per_s;
  unsigned buttons = 0;  // bit i: button i pressed
};

class HapticPort {
 public:
  virtual ~HapticPort() = default;
  // The probe state at `time_s` (the loop's clock). False on a device error.
  virtual bool read(double time_s, ProbeSample& sample) = 0;
  // Sends a force; the caller has already clamped it to max_force_N(). False on a device error.
  virtual bool write_force(const Vec3& force_N) = 0;
  virtual double max_force_N() const = 0;
};

}  // namespace vimg
