#pragma once
// Helpers for the render property tests: build images and gestures in memory, render offline,
// and measure the rendered drive (pulse times, zero-crossing frequency, envelope decay).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "player/drive_sinks.hpp"
#include "primitives/gesture.hpp"
#include "player/gesture_synth.hpp"
#include "player/offline_render.hpp"
#include "player/scene.hpp"
#include "primitives/image.hpp"

namespace vimg::test {

struct Rendered {
  std::vector<float> d;
  double rate_hz = 8000.0;
  double start_s = 0.0;
  double time_of(std::size_t i) const { return start_s + static_cast<double>(i) / rate_hz; }
  std::size_t index_at(double t) const {
    const double i = std::ceil((t - start_s) * rate_hz - 1e-9);
    return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(d.size())));
  }
  double peak(double from_s, double to_s) const {
    double p = 0.0;
    for (std::size_t i = index_at(from_s); i < std::min(d.size(), index_at(to_s)); ++i)
      p = std::max(p, static_cast<double>(std::fabs(d[i])));
    return p;
  }
  // First and last nonzero sample times within [from, to).
  std::optional<std::pair<double, double>> nonzero_span(double from_s, double to_s) const {
    std::optional<std::pair<double, double>> r;
    for (std::size_t i = index_at(from_s); i < std::min(d.size(), index_at(to_s)); ++i) {
      if (d[i] != 0.0f) {
        if (!r) r = std::pair{time_of(i), time_of(i)};
        r->second = time_of(i);
      }
    }
    return r;
  }
  // Frequency from interpolated upward zero crossings within [from, to).
  double zero_crossing_frequency_hz(double from_s, double to_s) const {
    std::vector<double> ups;
    for (std::size_t i = std::max<std::size_t>(1, index_at(from_s)); i < std::min(d.size(), index_at(to_s)); ++i) {
      const double a = d[i - 1], b = d[i];
      if (a < 0.0 && b >= 0.0) ups.push_back(time_of(i - 1) + (-a / (b - a)) / rate_hz);
    }
    if (ups.size() < 2) return 0.0;
    return static_cast<double>(ups.size() - 1) / (ups.back() - ups.front());
  }
  // Decay rate (1/s) of the envelope from a least-squares fit of ln|peak| over local maxima of |d|
  // within [from, to), counting only peaks in (floor, ceiling).
  double envelope_decay_per_s(double from_s, double to_s, double floor, double ceiling) const {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = std::max<std::size_t>(1, index_at(from_s)); i + 1 < std::min(d.size(), index_at(to_s)); ++i) {
      const double a = std::fabs(d[i - 1]), b = std::fabs(d[i]), c = std::fabs(d[i + 1]);
      if (b > a && b >= c && b > floor && b < ceiling) {
        const double x = time_of(i), y = std::log(b);
        sx += x; sy += y; sxx += x * x; sxy += x * y; ++n;
      }
    }
    if (n < 3) return 0.0;
    return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
  }
};

inline Rendered render(const Image& image, const Gesture& gesture, double rate_hz = 8000.0) {
  const auto scene = compile_scene(image);
  MemorySink sink;
  OfflineRenderOptions o;
  o.sample_rate_hz = rate_hz;
  const auto r = render_gesture(*scene, gesture, sink, o);
  return Rendered{sink.samples(), rate_hz, r.start_time_s};
}

inline Image image_of(std::vector<Element> children, double fullspeed_mm_per_s = 100.0) {
  Image img;
  img.width_mm = 100.0;
  img.height_mm = 100.0;
  InteractionParams p;
  p.full_speed_mm_per_s = fullspeed_mm_per_s;
  img.interaction = p;
  img.children = std::move(children);
  return img;
}

inline Element element(std::string id, std::variant<Dot, Line, Surface, Group, UnknownElement> body) {
  Element e;
  e.id = std::move(id);
  e.body = std::move(body);
  return e;
}

inline Dot dot(double x, double y, double r, double gain = 1.0) { return Dot{x, y, r, gain}; }
inline Line line(double x1, double y1, double x2, double y2, double width, double f, double zeta, double gain) {
  return Line{x1, y1, x2, y2, width, f, zeta, gain};
}
inline Surface rect_surface(double x, double y, double w, double h, double period, double relief, double gain,
                            SurfacePattern pattern = SurfacePattern::sine) {
  Surface s;
  s.shape = SurfaceShape::rect;
  s.x_mm = x; s.y_mm = y; s.width_mm = w; s.height_mm = h;
  s.period_mm = period; s.relief_mm = relief; s.gain = gain; s.pattern = pattern;
  return s;
}

inline GestureStroke line_stroke(double x0, double y0, double x1, double y1, double speed, double event_rate,
                                 double start_s = 0.0, int finger = 0, double hold_s = 0.0) {
  PathSpec p;
  p.kind = PathSpec::Kind::line;
  p.x0_mm = x0; p.y0_mm = y0; p.x1_mm = x1; p.y1_mm = y1;
  SamplingSpec s;
  s.speed_mm_per_s = speed; s.event_rate_hz = event_rate; s.start_time_s = start_s; s.finger = finger;
  s.hold_s = hold_s;
  return synthesise_stroke(p, s);
}

inline Gesture gesture_of(std::vector<GestureStroke> strokes) {
  Gesture g;
  g.strokes = std::move(strokes);
  return g;
}

}  // namespace vimg::test
