#pragma once
// The summary of one run of the haptic loop (vimg-force --telemetry, docs/volume-force-device.md): achieved
// and target rate, lateness p50/p99/max (LoopTelemetry's definitions), overruns, skips, cycles,
// the largest force sent against the clamp, clamp hits, dropped log rows, why the run ended and
// the device's state. As JSON: one object, numbers locale-independent.
//
// Threads: control thread (allocates).
#include <cstdint>
#include <string>

#include "player/haptic/haptic_loop.hpp"

namespace vimg {

struct ForceRunReport {
  double target_rate_hz = 0.0;
  LoopTimingStats timing;
  double max_force_N = 0.0;
  double clamp_N = 0.0;
  double max_slew_N_per_ms = 0.0;
  std::uint64_t clamp_hits = 0;
  std::uint64_t log_rows_dropped = 0;
  std::string exit_reason;   // "seconds elapsed", "SIGINT", "SIGTERM", "stopped", "device fault: ..."
  std::string device;        // "sim", "hid /dev/hidraw3 (1234:5678 ...)"
  std::string device_state;  // the loop's state: "stopped", "fault"
  std::string scheduling;    // "SCHED_FIFO 80", "normal priority (...)"
};

// Collects the loop's figures (after stop()).
ForceRunReport make_force_run_report(const HapticLoop& loop, std::string exit_reason, std::string device);

// {"rate_hz":…,"target_rate_hz":…,"jitter_p50_us":…,"jitter_p99_us":…,"jitter_max_us":…,
//  "overruns":…,"skips":…,"cycles":…,"elapsed_s":…,"max_force_N":…,"clamp_N":…,
//  "max_slew_N_per_ms":…,"clamp_hits":…,"log_rows_dropped":…,"exit_reason":"…","device":"…",
//  "device_state":"…","scheduling":"…"} and a newline.
std::string force_run_report_json(const ForceRunReport& report);

}  // namespace vimg
