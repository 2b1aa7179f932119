#pragma once
// Synthesised gestures: one finger along a line, an arc or a circle at a steady speed, sampled at a
// given event rate like a touchscreen, optionally with timing and position jitter.
#include <cstdint>
#include <optional>
#include <string>

#include "primitives/gesture.hpp"

namespace vimg {

struct PathSpec {
  enum class Kind { line, arc, circle } kind = Kind::line;
  // line
  double x0_mm = 0.0, y0_mm = 0.0, x1_mm = 0.0, y1_mm = 0.0;
  // arc and circle: centre, radius; angles in degrees, 0 = +x, increasing towards +y (clockwise on
  // screen, since y points down)
  double cx_mm = 0.0, cy_mm = 0.0, radius_mm = 0.0;
  double start_deg = 0.0, end_deg = 360.0;
};

struct SamplingSpec {
  double speed_mm_per_s = 100.0;  // > 0
  double event_rate_hz = 120.0;   // > 0: touch events per second
  double start_time_s = 0.0;
  double hold_s = 0.0;            // the finger rests at the end this long before lifting
  double pressure = 1.0;
  int finger = 0;
  double time_jitter_s = 0.0;     // each event time moves by up to +-time_jitter_s/2 (order kept)
  double position_jitter_mm = 0.0;  // Gaussian noise, standard deviation
  std::uint32_t seed = 1;
};

// Checks the specs; returns a problem in words, or nothing.
std::optional<std::string> check_synthesis(const PathSpec& path, const SamplingSpec& sampling);

// One stroke: down at the start of the path, moves at the event rate, up at the end (after hold_s).
GestureStroke synthesise_stroke(const PathSpec& path, const SamplingSpec& sampling);

// Length of the path in mm.
double path_length_mm(const PathSpec& path);

}  // namespace vimg
