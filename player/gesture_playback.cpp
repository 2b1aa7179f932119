#include "player/gesture_playback.hpp"

#include <algorithm>

namespace vimg {

namespace {

constexpr double kMetresPerMm = 1e-3;

Vec3 to_m(double x_mm, double y_mm) { return {x_mm * kMetresPerMm, y_mm * kMetresPerMm, 0.0}; }

// Index of the first point later than time_s.
std::size_t first_after(const std::vector<GesturePoint>& pts, double time_s) {
  return static_cast<std::size_t>(
      std::upper_bound(pts.begin(), pts.end(), time_s, [](double t, const GesturePoint& p) { return t < p.time_s; }) -
      pts.begin());
}

}  // namespace

GesturePlayback::GesturePlayback(const Gesture& gesture) {
  bool any = false;
  for (const auto& s : gesture.strokes) {
    if (s.points.empty()) continue;
    tracks_.push_back(Track{s.finger, s.points});
    start_time_s_ = any ? std::min(start_time_s_, s.points.front().time_s) : s.points.front().time_s;
    end_time_s_ = any ? std::max(end_time_s_, s.points.back().time_s) : s.points.back().time_s;
    any = true;
  }
}

Vec3 GesturePlayback::position_at(const Track& track, double time_s) {
  const auto& pts = track.points;
  const std::size_t k = first_after(pts, time_s);
  if (k == 0) return to_m(pts.front().x_mm, pts.front().y_mm);
  if (k == pts.size()) return to_m(pts.back().x_mm, pts.back().y_mm);
  const GesturePoint& a = pts[k - 1];
  const GesturePoint& b = pts[k];
  const double span = b.time_s - a.time_s;
  const double u = span > 0.0 ? (time_s - a.time_s) / span : 1.0;
  return to_m(a.x_mm + u * (b.x_mm - a.x_mm), a.y_mm + u * (b.y_mm - a.y_mm));
}

Vec3 GesturePlayback::velocity_at(const Track& track, double time_s) {
  const auto& pts = track.points;
  const std::size_t k = first_after(pts, time_s);
  if (k == 0 || k == pts.size()) return {};
  const GesturePoint& a = pts[k - 1];
  const GesturePoint& b = pts[k];
  const double span = b.time_s - a.time_s;
  if (span <= 0.0) return {};
  return to_m(b.x_mm - a.x_mm, b.y_mm - a.y_mm) / span;
}

void GesturePlayback::steps_at(double time_s, double dt_s, std::vector<FingerStep>& out) {
  out.clear();
  const double from_s = time_s - dt_s;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    const Track& t = tracks_[i];
    const double t0 = t.points.front().time_s;
    const double t1 = t.points.back().time_s;
    if (time_s < t0 || from_s >= t1) continue;
    const double a = std::max(from_s, t0);
    const double b = std::min(time_s, t1);
    FingerStep f;
    f.finger = t.finger;
    f.touch_id = static_cast<std::uint32_t>(i + 1);
    f.previous_position_m = position_at(t, a);
    f.position_m = position_at(t, b);
    f.velocity_m_per_s = velocity_at(t, 0.5 * (a + b));
    const std::size_t k = first_after(t.points, b);
    f.pressure = t.points[k == 0 ? 0 : k - 1].pressure;
    out.push_back(f);
  }
}

std::size_t GesturePlayback::max_simultaneous_touches() const {
  std::vector<std::pair<double, int>> events;
  for (const auto& t : tracks_) {
    events.emplace_back(t.points.front().time_s, 1);
    events.emplace_back(t.points.back().time_s, -1);
  }
  std::sort(events.begin(), events.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first < y.first : x.second > y.second;
  });
  int n = 0, best = 0;
  for (const auto& e : events) best = std::max(best, n += e.second);
  return static_cast<std::size_t>(best);
}

}  // namespace vimg
