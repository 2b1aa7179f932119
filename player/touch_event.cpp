#include "player/touch_event.hpp"

#include <ctime>

namespace vimg {

double monotonic_time_s() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace vimg
