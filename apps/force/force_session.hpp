#pragma once
// One run of vimg-force: load the scene (and the hand's path), open the device, run the haptic
// loop until --seconds, a signal or a fault, then put the device at rest, complete the log and
// the telemetry, and say how it ended. main() only parses the arguments and catches the signals.
#include <atomic>

#include "apps/force/force_args.hpp"

namespace vimg::force_app {

// `signal_received` is set (to SIGINT or SIGTERM) by the signal handler; the session polls it.
// Returns the exit status (0, 1, 130 or 143; see --help).
int run_force_session(const ForceArgs& args, const std::atomic<int>& signal_received);

}  // namespace vimg::force_app
