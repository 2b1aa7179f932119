#pragma once
// What the haptic loop needs of a force device: read the probe, send a force, know the device's
// limits and, after an error, why. hal/force's ForceDevice is this interface for real and
// simulated devices; tests wrap it.
//
// Threads: one thread at a time drives a port; in the haptic loop that is the loop thread, so
// read(), write_force() and last_fault() neither allocate, lock nor throw, and block on nothing
// but the device itself.
#include <cstdint>

#include "primitives/vec3.hpp"

namespace vimg {

struct ProbeSample {
  Vec3 position_m;
  Vec3 velocity_m_per_s;
  unsigned buttons = 0;  // bit i: button i pressed
  // Counts the device's measurements: it changes when, and only when, the device has measured the
  // probe again since the previous read (the HID device from its state report sequence, the
  // simulated device on every read that advances its time). The safety stack's watchdog faults
  // when it stays the same for too many cycles.
  std::uint64_t sequence = 0;
};

// The slew limit a device gets when its description gives none: 1 N per ms suits a Touch-class
// desktop device (a full 3.3 N step takes 3.3 ms).
inline constexpr double kDefaultMaxSlew_N_per_ms = 1.0;

// What a device can render safely.
struct ForceDeviceLimits {
  double max_force_N = 3.3;              // Fmax
  double max_stiffness_N_per_m = 400.0;  // Kmax
  Vec3 workspace_m{0.16, 0.12, 0.12};    // full extents, centred on the origin
  double max_slew_N_per_ms = kDefaultMaxSlew_N_per_ms;  // largest force change per millisecond
};

// Why a read or write failed.
enum class PortFault : std::uint8_t {
  none = 0,
  io_error,      // a transfer failed: unplugged, no permission, bus error
  device_fault,  // the device reported a fault of its own (motor driver, its own watchdog)
  no_data,       // the device has never sent a probe position
};

// "transfer failed (unplugged?)", ... : static text, safe on any thread.
const char* describe(PortFault fault) noexcept;

class HapticPort {
 public:
  virtual ~HapticPort() = default;
  // The probe state at `time_s` (the loop's clock). False on a device error (see last_fault()).
  virtual bool read(double time_s, ProbeSample& sample) = 0;
  // Sends a force; the caller has already clamped it. False on a device error.
  virtual bool write_force(const Vec3& force_N) = 0;
  virtual ForceDeviceLimits limits() const = 0;
  // Why the last failed read or write failed; io_error unless the device knows better.
  virtual PortFault last_fault() const noexcept { return PortFault::io_error; }

  double max_force_N() const { return limits().max_force_N; }
};

}  // namespace vimg
