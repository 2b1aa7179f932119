#include "apps/force/status_line.hpp"

#include <cstdio>

namespace vimg::force_app {

std::string format_status_line(const HapticLoopStatus& s) {
  char text[160];
  std::snprintf(text, sizeof text, "%.1f Hz  jitter p99 %.0f us  %llu overruns  max |F| %.2f N  %s", s.timing.rate_hz,
                s.timing.jitter_p99_us, static_cast<unsigned long long>(s.timing.overruns), s.max_force_N, describe(s.state));
  return text;
}

}  // namespace vimg::force_app
