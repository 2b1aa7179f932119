#include "primitives/geometry/hit_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace vimg {

namespace {

double distance_squared_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length_squared = dot(ab, ab);
  const double t = length_squared > 0.0 ? std::clamp(dot(p - a, ab) / length_squared, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + ab * t);
  return dot(d, d);
}

// True if p lies within the tolerance of the edge a-b. The box test rejects most edges cheaply.
bool on_edge(const Vec2& p, const Vec2& a, const Vec2& b) {
  constexpr double tol = kBoundaryTolerance_m;
  if (p.x < std::min(a.x, b.x) - tol || p.x > std::max(a.x, b.x) + tol || p.y < std::min(a.y, b.y) - tol ||
      p.y > std::max(a.y, b.y) + tol) {
    return false;
  }
  return distance_squared_to_segment(p, a, b) <= tol * tol;
}

}  // namespace

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  return std::sqrt(distance_squared_to_segment(p, a, b));
}

bool contains(const Disc& disc, const Vec2& p) {
  const Vec2 d = p - disc.centre;
  return dot(d, d) <= disc.radius * disc.radius;
}

bool contains(const Capsule& capsule, const Vec2& p) {
  return distance_squared_to_segment(p, capsule.a, capsule.b) <= capsule.radius * capsule.radius;
}

bool contains(const Rect& rect, const Vec2& p) {
  return p.x >= rect.min.x && p.x <= rect.max.x && p.y >= rect.min.y && p.y <= rect.max.y;
}

bool contains(const Ellipse& ellipse, const Vec2& p) {
  if (!(ellipse.rx > 0.0) || !(ellipse.ry > 0.0)) return false;
  const double u = (p.x - ellipse.centre.x) / ellipse.rx;
  const double v = (p.y - ellipse.centre.y) / ellipse.ry;
  return u * u + v * v <= 1.0;
}

bool contains(const Polygon& polygon, const Vec2& p) {
  const auto& v = polygon.vertices;
  const std::size_t n = v.size();
  if (n < 3) return false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    if (on_edge(p, v[j], v[i])) return true;
  }
  // Even-odd rule with the half-open convention on y, so a ray through a vertex counts once.
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = v[j];
    const Vec2& b = v[i];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x_at_y = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x_at_y) inside = !inside;
    }
  }
  return inside;
}

}  // namespace vimg
