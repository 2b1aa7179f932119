#pragma once
// A touch panel that reports a gesture late, and the player behind it (`vimg render
// --touch-latency-ms`, docs/latency.md): each row of the gesture reaches a LiveTracker
// latency_s after its time, stamped with its arrival (as a live player stamps events), and the
// tracker predicts each finger horizon ahead as the live player would: compensation on, the
// panel's latency (a file's output path adds none); off, the tracker's dead reckoning alone.
// Steps come out as GesturePlayback's do, so the same offline renderer plays either.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "player/finger_step.hpp"
#include "primitives/gesture.hpp"
#include "player/live_tracker.hpp"
#include "player/touch_event.hpp"

namespace vimg {

struct PanelSimulation {
  double latency_s = 0.0;    // 0 .. kMaxTouchPanelLatency_s
  bool compensation = true;  // predict latency_s ahead (the players' default)
  TouchPredictionModel model = kDefaultTouchPredictionModel;
};

// Why a gesture cannot go through the simulated panel ("" when it can): the live tracker follows
// fingers 0 .. LiveTracker::kMaxFingers - 1.
std::string panel_simulation_problem(const Gesture& gesture);

class SimulatedPanel {
 public:
  SimulatedPanel(const Gesture& gesture, const PanelSimulation& simulation);

  // As GesturePlayback::steps_at: the fingers in contact during the step ending at time_s.
  void steps_at(double time_s, double dt_s, std::vector<FingerStep>& out);
  double start_time_s() const { return start_time_s_; }
  double end_time_s() const { return end_time_s_; }

 private:
  std::vector<TouchEvent> events_;  // by arrival time
  std::size_t next_ = 0;
  LiveTracker tracker_;
  double start_time_s_ = 0.0;
  double end_time_s_ = 0.0;
};

}  // namespace vimg
