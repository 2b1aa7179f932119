#include "player/haptic/safe_haptic_cycle.hpp"

namespace vimg {

ForceCycleRecord SafeHapticCycle::step(HapticPort& port, double time_s, bool previous_overran) {
  ForceCycleRecord record;
  record.time_s = time_s;
  ProbeSample probe = last_probe_;
  if (!port.read(time_s, probe)) {
    record.position_m = last_probe_.position_m;
    record.port_fault = port.last_fault();
    record.fault = ForceFault::device_read;
    record.flags = safety_.device_fault(record.fault).flags;
    port.write_force({});  // zero first; if the device is gone, its own watchdog zeroes it
    return record;
  }
  last_probe_ = probe;
  record.position_m = probe.position_m;
  const CycleOutput rendered = render_.step(probe, time_s);
  const SafetyOutput safe = safety_.apply({time_s, rendered.total_N, probe.position_m, probe.sequence, previous_overran});
  record.flags = safe.flags;
  record.fault = safe.fault;
  if (!port.write_force(safe.force_N)) {
    record.port_fault = port.last_fault();
    record.fault = ForceFault::device_write;
    record.flags = safety_.device_fault(record.fault).flags;
    port.write_force({});
    return record;
  }
  record.force_N = safe.force_N;
  return record;
}

ForceCycleRecord SafeHapticCycle::stop(HapticPort& port, double time_s) {
  ForceCycleRecord record;
  record.time_s = time_s;
  record.position_m = last_probe_.position_m;
  record.flags = safety_.stop().flags;
  record.fault = safety_.fault();
  if (!port.write_force({})) record.port_fault = port.last_fault();
  return record;
}

void SafeHapticCycle::reset() noexcept { safety_.reset(); }

}  // namespace vimg
