#pragma once
// Ten fingers from the shared touch traces (tests/data/touch-latency-henze2017, read as
// bench/henze_traces.hpp reads them): the ten longest strokes of participants 1-4's writing and
// drawing, each moved so that it starts on the smiley's face (assets/examples/smiley.vimg), one per
// finger, as live events (down, moves, up) in time order: 30 ms apart, or, with one_after_another,
// each 0.2 s after the one before has lifted. Real timing (60 Hz panels with jitter), real stops and
// turns.
#include <algorithm>
#include <string>
#include <vector>

#include "bench/henze_traces.hpp"
#include "player/touch_event.hpp"

namespace vimg::test {

inline std::vector<TouchEvent> ten_trace_fingers(bool one_after_another = false) {
  const std::string dir = std::string(VIMG_TEST_DATA_DIR) + "/touch-latency-henze2017";
  std::vector<TouchStroke> strokes = henze_traces::task_strokes(dir, "WriteTasks");
  for (TouchStroke& s : henze_traces::task_strokes(dir, "PaintTasks")) strokes.push_back(std::move(s));
  std::stable_sort(strokes.begin(), strokes.end(),
                   [](const TouchStroke& a, const TouchStroke& b) { return a.events.size() > b.events.size(); });
  std::vector<TouchEvent> events;
  double start_s = 0.0;
  for (int finger = 0; finger < 10 && finger < static_cast<int>(strokes.size()); ++finger) {
    const std::vector<FingerHistory::Point>& points = strokes[static_cast<std::size_t>(finger)].events;
    const FingerHistory::Point& first = points.front();
    const double start_x_mm = 15.0 + 4.0 * finger, start_y_mm = 45.0 + 5.0 * finger;
    start_s = one_after_another ? (events.empty() ? 0.0 : events.back().time_s + 0.2) : 0.03 * finger;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const FingerHistory::Point& p = points[i];
      const TouchPhase phase = i == 0 ? TouchPhase::down : i + 1 == points.size() ? TouchPhase::up : TouchPhase::move;
      events.push_back({p.time_s - first.time_s + start_s, finger, phase, start_x_mm + p.x_mm - first.x_mm,
                        start_y_mm + p.y_mm - first.y_mm, 1.0});
    }
  }
  std::stable_sort(events.begin(), events.end(), [](const TouchEvent& a, const TouchEvent& b) { return a.time_s < b.time_s; });
  return events;
}

}  // namespace vimg::test
