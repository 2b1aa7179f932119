#pragma once
// The shared touch traces (tests/data/touch-latency-henze2017: participants 1-4 of one task) as the
// prediction protocol's strokes in mm, read as `vimg gesture import --px-per-mm 12.72` reads them.
// Used by bench/touch_prediction_bench.cpp and tests/touch_prediction/prediction_protocol_test.cpp.
#include <cstdio>
#include <string>
#include <vector>

#include "player/gesture_prediction.hpp"
#include "player/touch_trace_gesture.hpp"
#include "primitives/touch_prediction/prediction_protocol.hpp"
#include "storage/touch_trace/evdev_trace.hpp"

namespace vimg::henze_traces {

inline constexpr double kPxPerMm = 12.72;  // the paper: 10 mm = 127.20 px

// `prefix`: WriteTasks, PaintTasks or FittsTasks. A file that does not read is reported on stderr
// and left out (the caller checks what it got).
inline std::vector<TouchStroke> task_strokes(const std::string& dir, const std::string& prefix) {
  std::vector<TouchStroke> all;
  for (int participant = 1; participant <= 4; ++participant) {
    const std::string path = dir + "/" + prefix + "-participant" + std::to_string(participant) + ".txt";
    const TouchTraceParseResult trace = load_touch_trace(path);
    for (const Diagnostic& d : trace.diagnostics) std::fprintf(stderr, "%s\n", d.to_string().c_str());
    if (!trace.trace) continue;
    TouchMapping mapping;
    mapping.units_per_mm = kPxPerMm;
    const TraceGestureResult g = trace_to_gesture(*trace.trace, mapping, path);
    for (const std::string& e : g.errors) std::fprintf(stderr, "%s\n", e.c_str());
    if (!g.gesture) continue;
    for (TouchStroke& s : touch_strokes_of(*g.gesture)) all.push_back(std::move(s));
  }
  return all;
}

}  // namespace vimg::henze_traces
