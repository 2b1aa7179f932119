#pragma once
// The one-line status vimg-force rewrites in place each second on a terminal:
//   "1000.0 Hz  jitter p99 45 us  0 overruns  max |F| 1.23 N  running"
#include <string>

#include "player/haptic/haptic_loop.hpp"

namespace vimg::force_app {

std::string format_status_line(const HapticLoopStatus& status);

}  // namespace vimg::force_app
