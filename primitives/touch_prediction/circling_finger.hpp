#pragma once
// The workload both cost benchmarks of the predictor measure (bench/touch_prediction_bench.cpp
// natively, vimg_bench_predict in the wasm through bench/web_render_bench.mjs), so their ns per
// prediction compare the same work: a finger circling at 150 mm/s (radius 20 mm, 7.5 rad/s),
// 60 events a second, for one second.
#include <cmath>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg {

inline FingerHistory circling_finger_history() {
  FingerHistory h;
  for (int i = 0; i <= 60; ++i) {
    const double t = i / 60.0;
    add_finger_event(h, t, 30.0 + 20.0 * std::cos(7.5 * t), 30.0 + 20.0 * std::sin(7.5 * t));
  }
  return h;
}

// The horizon sequence both benchmarks step through: 33 ms to 100 ms by 0.1 ms, then again (not a
// constant the compiler can fold).
inline double next_bench_horizon_s(double horizon_s) { return horizon_s < 0.1 ? horizon_s + 1e-4 : 0.033; }

}  // namespace vimg
