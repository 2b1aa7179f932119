#pragma once
// The standard exploration (docs/studies.md, "The standard exploration"): the rubbing `vimg compare`
// renders every image under when no --gesture is given, standing for a participant of the matching
// test who rubs the whole screen without seeing the picture. One finger, at each of three speeds
// (slow, medium, fast: 40, 100 and 250 mm/s by default), first sweeps the canvas in horizontal passes
// and then in vertical passes:
//   - a pass runs from one edge of the canvas to the other; consecutive passes are joined along the
//     edge (a serpentine, the finger stays down), so each (speed, direction) is one stroke;
//   - passes are pass_spacing_mm apart (10 mm); the passes of the k-th of K speeds are offset by
//     spacing * (k + 0.5) / K, so that each speed covers the canvas evenly and the three together
//     cross it every spacing / 3 (3.3 mm: a DOT of radius 1.7 mm or more is always touched);
//   - the finger lifts for gap_s (0.1 s) between strokes; touch events at 120 Hz, as a touchscreen
//     reports them, without jitter (the exploration is the same for every image and every run);
//   - a large canvas widens the spacing (by steps of 25 %) until the whole exploration lasts at most
//     max_duration_s (120 s), which bounds the cost of a comparison; a canvas so large that one pass
//     per speed and direction lasts longer (width + height beyond about 3 m) has no standard
//     exploration: give gestures instead.
// On a 60 x 110 mm canvas (the bundled matching sets) it lasts 58 s; on 100 x 100 mm, 86 s.
// Pure functions; built with player/gesture_synth.hpp.
#include <optional>
#include <string>
#include <vector>

#include "primitives/gesture.hpp"

namespace vimg::study {

struct ExplorationSpec {
  std::vector<double> speeds_mm_per_s{40.0, 100.0, 250.0};  // each > 0
  double pass_spacing_mm = 10.0;                             // > 0
  double event_rate_hz = 120.0;                              // touch events per second
  double gap_s = 0.1;                                        // finger lifted between strokes
  double max_duration_s = 120.0;                             // the spacing widens beyond this
};

struct Exploration {
  Gesture gesture;               // finger 0, strokes one after another from time 0
  double pass_spacing_mm = 0.0;  // as used (wider than asked on a large canvas)
  double duration_s = 0.0;       // the last lift
  ExplorationSpec spec;          // as asked
};

// The exploration of a width_mm x height_mm canvas (both > 0); nothing when it cannot last at most
// spec.max_duration_s.
std::optional<Exploration> standard_exploration(double width_mm, double height_mm, const ExplorationSpec& spec = {});

// One line for reports: "horizontal and vertical serpentine passes 10 mm apart at 40, 100 and
// 250 mm/s, 58.2 s".
std::string describe(const Exploration& exploration);

}  // namespace vimg::study
