#include "player/simulated_panel.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace vimg {

std::string panel_simulation_problem(const Gesture& gesture) {
  for (const GestureStroke& s : gesture.strokes) {
    if (s.finger < 0 || s.finger >= LiveTracker::kMaxFingers) {
      return "a simulated panel follows fingers 0 to " + std::to_string(LiveTracker::kMaxFingers - 1) +
             " (the live tracker's); the gesture has finger " + std::to_string(s.finger);
    }
  }
  return {};
}

SimulatedPanel::SimulatedPanel(const Gesture& gesture, const PanelSimulation& simulation) {
  const double latency_s = std::isfinite(simulation.latency_s) ? std::max(0.0, simulation.latency_s) : 0.0;
  for (const GestureStroke& s : gesture.strokes) {
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const GesturePoint& p = s.points[i];
      const TouchPhase phase = i == 0 ? TouchPhase::down : (i + 1 == s.points.size() ? TouchPhase::up : TouchPhase::move);
      events_.push_back({p.time_s + latency_s, s.finger, phase, p.x_mm, p.y_mm, p.pressure});
    }
  }
  std::stable_sort(events_.begin(), events_.end(),
                   [](const TouchEvent& a, const TouchEvent& b) { return a.time_s < b.time_s; });
  start_time_s_ = gesture.start_time_s() + latency_s;
  end_time_s_ = gesture.end_time_s() + latency_s;
  tracker_.set_prediction(simulation.compensation ? latency_s : 0.0, simulation.model);
}

void SimulatedPanel::steps_at(double time_s, double dt_s, std::vector<FingerStep>& out) {
  while (next_ < events_.size() && events_[next_].time_s <= time_s) tracker_.apply(events_[next_++], time_s);
  std::array<FingerStep, LiveTracker::kMaxFingers> steps{};
  const std::size_t n = tracker_.steps_at(time_s, dt_s, steps);
  out.assign(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(n));
}

}  // namespace vimg
