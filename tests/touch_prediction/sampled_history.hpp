#pragma once
// A finger history sampled from a path (t -> (x_mm, y_mm)) at `rate_hz` for `duration_s`, the
// last event at time t_end: the tests' way to build histories with known motion.
#include <cmath>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg::test {

template <class Path>
FingerHistory history_of(Path path, double rate_hz, double duration_s, double t_end = 10.0) {
  FingerHistory h;
  const int n = static_cast<int>(std::lround(duration_s * rate_hz));
  for (int i = n; i >= 0; --i) {
    const double t = t_end - i / rate_hz;
    const auto [x, y] = path(t);
    add_finger_event(h, t, x, y);
  }
  return h;
}

}  // namespace vimg::test
