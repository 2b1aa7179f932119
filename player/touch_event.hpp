#pragma once
// A live input event (touchscreen, mouse) on its way to the real-time renderer.
#include <cstdint>

#include "realtime/clock.hpp"  // monotonic_s(): the time base of TouchEvent

namespace vimg {

enum class TouchPhase : std::uint8_t { down, move, up };

struct TouchEvent {
  double time_s = 0.0;  // on the renderer's clock: monotonic_s() when the event happened
  int finger = 0;       // 0 .. LiveTracker::kMaxFingers - 1
  TouchPhase phase = TouchPhase::move;
  double x_mm = 0.0;
  double y_mm = 0.0;
  double pressure = 1.0;
};

}  // namespace vimg
