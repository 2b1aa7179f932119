#pragma once
// The felt-onset scenario of docs/latency.md, shared by bench/touch_prediction_bench.cpp and
// tests/touch_prediction/render_latency_test.cpp: three vertical LINEs 30 mm apart on a 120 mm
// canvas, crossed by a finger on a wave (amplitude 15 mm, wavelength 60 mm) at 150 mm/s, reported
// 60 times a second; rendered at 8 kHz exactly, or through a simulated late panel.
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "player/drive_onsets.hpp"
#include "player/drive_sinks.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"

namespace vimg::latency_scenario {

inline constexpr double kRate_hz = 8000.0;
inline constexpr double kSpeed_mm_per_s = 150.0;

inline Image lines_image() {
  Image image;
  image.width_mm = image.height_mm = 120.0;
  for (double x : {25.0, 55.0, 85.0}) {
    Element e;
    e.body = decltype(e.body)(Line{x, 0.0, x, 120.0});  // a whole variant: GCC's -O1 sees no uninitialised member
    image.children.push_back(e);
  }
  return image;
}

inline Gesture curved_swipe() {
  GestureStroke s;
  double x = 5.0, t = 0.0;
  const double dt = 1.0 / 60.0, k = 2.0 * std::numbers::pi / 60.0;
  while (x < 110.0) {
    s.points.push_back({t, x, 60.0 + 15.0 * std::sin(k * x), 1.0});
    const double slope = 15.0 * k * std::cos(k * x);
    x += kSpeed_mm_per_s * dt / std::sqrt(1.0 + slope * slope);  // 150 mm/s along the path
    t += dt;
  }
  Gesture g;
  g.strokes.push_back(s);
  return g;
}

// The onsets of the render, exact (no panel) or through `panel`.
inline std::vector<double> onsets(const Gesture& g, std::optional<PanelSimulation> panel) {
  const auto scene = compile_scene(lines_image());
  MemorySink sink;
  OfflineRenderOptions options;
  options.sample_rate_hz = kRate_hz;
  options.panel = panel;
  const OfflineRenderResult r = render_gesture(*scene, g, sink, options);
  return drive_onsets_s(sink.samples(), kRate_hz, r.start_time_s);
}

}  // namespace vimg::latency_scenario
