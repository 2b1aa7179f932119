#include "study/exploration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "player/gesture_synth.hpp"

namespace vimg::study {

namespace {

struct Point {
  double x_mm, y_mm;
};

// The pass positions across `extent_mm` for speed k of `speeds`: offset spacing * (k + 0.5) / K,
// then every spacing; at least one pass (in the middle when the canvas is narrower than the offset).
std::vector<double> pass_positions(double extent_mm, double spacing_mm, std::size_t k, std::size_t speeds) {
  std::vector<double> at;
  const double offset = spacing_mm * (static_cast<double>(k) + 0.5) / static_cast<double>(speeds);
  for (double p = offset; p < extent_mm; p += spacing_mm) at.push_back(p);
  if (at.empty()) at.push_back(extent_mm / 2.0);
  return at;
}

// The serpentine through passes across a canvas (horizontal: rows at `positions` from x = 0 to
// x = width; vertical: the same with x and y exchanged).
std::vector<Point> serpentine(const std::vector<double>& positions, double length_mm, bool horizontal) {
  std::vector<Point> corners;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const bool forward = i % 2 == 0;
    const double a = forward ? 0.0 : length_mm;
    const double b = forward ? length_mm : 0.0;
    corners.push_back(horizontal ? Point{a, positions[i]} : Point{positions[i], a});
    corners.push_back(horizontal ? Point{b, positions[i]} : Point{positions[i], b});
  }
  return corners;
}

double polyline_length_mm(const std::vector<Point>& corners) {
  double length = 0.0;
  for (std::size_t i = 1; i < corners.size(); ++i)
    length += std::hypot(corners[i].x_mm - corners[i - 1].x_mm, corners[i].y_mm - corners[i - 1].y_mm);
  return length;
}

// One stroke along the corners at a steady speed from `start_s`: each straight piece synthesised
// by gesture_synth, joined where they meet.
GestureStroke stroke_along(const std::vector<Point>& corners, double speed_mm_per_s, double event_rate_hz,
                           double start_s) {
  GestureStroke stroke;
  double t = start_s;
  for (std::size_t i = 1; i < corners.size(); ++i) {
    PathSpec path;
    path.x0_mm = corners[i - 1].x_mm;
    path.y0_mm = corners[i - 1].y_mm;
    path.x1_mm = corners[i].x_mm;
    path.y1_mm = corners[i].y_mm;
    SamplingSpec sampling;
    sampling.speed_mm_per_s = speed_mm_per_s;
    sampling.event_rate_hz = event_rate_hz;
    sampling.start_time_s = t;
    const GestureStroke piece = synthesise_stroke(path, sampling);
    const std::size_t first = stroke.points.empty() ? 0 : 1;  // the join is already there
    stroke.points.insert(stroke.points.end(), piece.points.begin() + static_cast<std::ptrdiff_t>(first),
                         piece.points.end());
    t = stroke.points.back().time_s;
  }
  return stroke;
}

std::vector<std::vector<Point>> all_paths(double width_mm, double height_mm, double spacing_mm, std::size_t speeds,
                                          std::size_t k) {
  return {serpentine(pass_positions(height_mm, spacing_mm, k, speeds), width_mm, true),
          serpentine(pass_positions(width_mm, spacing_mm, k, speeds), height_mm, false)};
}

double duration_s(double width_mm, double height_mm, double spacing_mm, const ExplorationSpec& spec) {
  double total = 0.0;
  const std::size_t n = spec.speeds_mm_per_s.size();
  for (std::size_t k = 0; k < n; ++k) {
    for (const auto& path : all_paths(width_mm, height_mm, spacing_mm, n, k))
      total += polyline_length_mm(path) / spec.speeds_mm_per_s[k] + spec.gap_s;
  }
  return total - spec.gap_s;
}

}  // namespace

std::optional<Exploration> standard_exploration(double width_mm, double height_mm, const ExplorationSpec& spec) {
  Exploration e;
  e.spec = spec;
  e.pass_spacing_mm = spec.pass_spacing_mm;
  // Each step of 25 % shortens a long exploration by nearly a fifth; the canvas is at most
  // 10 m wide (storage/limits.hpp), so this ends after a few dozen steps.
  while (duration_s(width_mm, height_mm, e.pass_spacing_mm, spec) > spec.max_duration_s &&
         e.pass_spacing_mm < std::max(width_mm, height_mm)) {
    e.pass_spacing_mm *= 1.25;
  }
  if (duration_s(width_mm, height_mm, e.pass_spacing_mm, spec) > spec.max_duration_s) return std::nullopt;
  const std::size_t n = spec.speeds_mm_per_s.size();
  double t = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    for (const auto& path : all_paths(width_mm, height_mm, e.pass_spacing_mm, n, k)) {
      e.gesture.strokes.push_back(stroke_along(path, spec.speeds_mm_per_s[k], spec.event_rate_hz, t));
      t = e.gesture.strokes.back().points.back().time_s + spec.gap_s;
    }
  }
  e.duration_s = e.gesture.end_time_s();
  return e;
}

std::string describe(const Exploration& e) {
  std::string speeds;
  const auto& v = e.spec.speeds_mm_per_s;
  for (std::size_t i = 0; i < v.size(); ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", v[i]);
    speeds += (i == 0 ? "" : i + 1 == v.size() ? " and " : ", ") + std::string(number);
  }
  char line[256];
  std::snprintf(line, sizeof line, "horizontal and vertical serpentine passes %g mm apart at %s mm/s, %.1f s",
                e.pass_spacing_mm, speeds.c_str(), e.duration_s);
  return line;
}

}  // namespace vimg::study
