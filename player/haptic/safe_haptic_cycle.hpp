#pragma once
// One whole cycle of the force loop, without threads or clocks: read the probe, render the scene
// (HapticCycle), apply the safety stack (SafetyStack), write the force. The loop thread runs it at
// its deadlines; tests run it with a simulated clock, deterministically.
//
//   step(): a failed read or write sends zero at once (flag device) and reports the fault; a
//           fault of the safety stack (stale input, overruns) has already zeroed the force;
//   stop(): sends zero at once (flag stop), without reading.
//
// Threads: one thread at a time (the loop thread); never allocates, locks or throws itself, and
// blocks only in the device's read and write.
#include <cstdint>

#include "player/haptic/haptic_cycle.hpp"
#include "player/haptic/safety_stack.hpp"

namespace vimg {

// What one cycle did: the loop logs it and publishes it; trivially copyable for the SPSC ring.
struct ForceCycleRecord {
  double time_s = 0.0;
  Vec3 position_m;  // the probe as read (the last good position when the read failed)
  Vec3 force_N;     // the force sent, after the safety stack
  std::uint32_t flags = 0;  // safety_flag bits
  ForceFault fault = ForceFault::none;
  PortFault port_fault = PortFault::none;  // with device_read / device_write: what the device said
};

class SafeHapticCycle {
 public:
  SafeHapticCycle(const ForceDeviceLimits& device, const SafetySettings& safety, HapticCycleConfig render,
                  double period_s)
      : render_(render), safety_(safety, device, period_s) {}

  HapticCycle& render() { return render_; }
  SafetyStack& safety() { return safety_; }
  const SafetyStack& safety() const { return safety_; }

  ForceCycleRecord step(HapticPort& port, double time_s, bool previous_overran);
  ForceCycleRecord stop(HapticPort& port, double time_s);
  // Re-arms the safety stack (gate, watchdogs, fault) for a new run; the scenes stay.
  void reset() noexcept;

 private:
  HapticCycle render_;
  SafetyStack safety_;
  ProbeSample last_probe_;
};

}  // namespace vimg
