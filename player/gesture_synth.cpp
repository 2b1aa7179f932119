#include "player/gesture_synth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace vimg {

namespace {

double deg_to_rad(double d) { return d * std::numbers::pi / 180.0; }

// Point at arc length s along the path.
void point_at(const PathSpec& p, double s_mm, double& x, double& y) {
  const double len = path_length_mm(p);
  const double u = len > 0.0 ? std::clamp(s_mm / len, 0.0, 1.0) : 0.0;
  if (p.kind == PathSpec::Kind::line) {
    x = p.x0_mm + u * (p.x1_mm - p.x0_mm);
    y = p.y0_mm + u * (p.y1_mm - p.y0_mm);
    return;
  }
  const double a0 = deg_to_rad(p.start_deg);
  const double a1 = p.kind == PathSpec::Kind::circle ? a0 + 2.0 * std::numbers::pi : deg_to_rad(p.end_deg);
  const double a = a0 + u * (a1 - a0);
  x = p.cx_mm + p.radius_mm * std::cos(a);
  y = p.cy_mm + p.radius_mm * std::sin(a);
}

bool finite_all(std::initializer_list<double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

double path_length_mm(const PathSpec& p) {
  switch (p.kind) {
    case PathSpec::Kind::line: return std::hypot(p.x1_mm - p.x0_mm, p.y1_mm - p.y0_mm);
    case PathSpec::Kind::arc: return std::fabs(deg_to_rad(p.end_deg - p.start_deg)) * p.radius_mm;
    case PathSpec::Kind::circle: return 2.0 * std::numbers::pi * p.radius_mm;
  }
  return 0.0;
}

std::optional<std::string> check_synthesis(const PathSpec& p, const SamplingSpec& s) {
  if (!finite_all({p.x0_mm, p.y0_mm, p.x1_mm, p.y1_mm, p.cx_mm, p.cy_mm, p.radius_mm, p.start_deg, p.end_deg}))
    return "path values must be finite numbers";
  if (p.kind != PathSpec::Kind::line && !(p.radius_mm > 0.0)) return "radius must be > 0";
  if (!(s.speed_mm_per_s > 0.0) || !std::isfinite(s.speed_mm_per_s)) return "speed must be > 0";
  if (!(s.event_rate_hz > 0.0) || !(s.event_rate_hz <= 100000.0)) return "event rate must be in (0, 100000] Hz";
  if (!std::isfinite(s.start_time_s)) return "start time must be finite";
  if (!(s.hold_s >= 0.0) || !std::isfinite(s.hold_s)) return "hold must be >= 0";
  if (!(s.pressure >= 0.0 && s.pressure <= 1.0)) return "pressure must be in [0, 1]";
  if (s.finger < 0 || s.finger > kMaxGestureFinger) return "finger must be in 0.." + std::to_string(kMaxGestureFinger);
  if (!(s.time_jitter_s >= 0.0) || !(s.time_jitter_s * s.event_rate_hz < 1.0))
    return "time jitter must be >= 0 and shorter than one event interval";
  if (!(s.position_jitter_mm >= 0.0) || !std::isfinite(s.position_jitter_mm)) return "position jitter must be >= 0";
  const double duration = path_length_mm(p) / s.speed_mm_per_s;
  if (duration * s.event_rate_hz > 1e7) return "too many events (more than 10 million)";
  return std::nullopt;
}

GestureStroke synthesise_stroke(const PathSpec& p, const SamplingSpec& s) {
  GestureStroke stroke;
  stroke.finger = s.finger;
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> time_noise(-0.5 * s.time_jitter_s, 0.5 * s.time_jitter_s);
  std::normal_distribution<double> pos_noise(0.0, 1.0);
  const double duration = path_length_mm(p) / s.speed_mm_per_s;
  const double interval = 1.0 / s.event_rate_hz;
  auto add = [&](double t_rel, bool exact) {
    double x = 0.0, y = 0.0;
    point_at(p, std::min(t_rel, duration) * s.speed_mm_per_s, x, y);
    if (!exact && s.position_jitter_mm > 0.0) {
      x += s.position_jitter_mm * pos_noise(rng);
      y += s.position_jitter_mm * pos_noise(rng);
    }
    stroke.points.push_back({s.start_time_s + t_rel, x, y, s.pressure});
  };
  add(0.0, true);
  const auto n = static_cast<long long>(std::floor(duration / interval));
  double last = 0.0;
  for (long long k = 1; k <= n; ++k) {
    double t = static_cast<double>(k) * interval;
    if (s.time_jitter_s > 0.0) t += time_noise(rng);
    t = std::clamp(t, last, duration);
    if (t >= duration) break;
    add(t, false);
    last = t;
  }
  add(duration, true);
  if (s.hold_s > 0.0) add(duration + s.hold_s, true);
  return stroke;
}

}  // namespace vimg
