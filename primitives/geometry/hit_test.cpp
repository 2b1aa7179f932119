#include "primitives/geometry/hit_test.hpp"

#include <algorithm>
#include <cstddef>

namespace vimg {

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length_squared = dot(ab, ab);
  if (length_squared == 0.0) return norm(p - a);
  const double t = std::clamp(dot(p - a, ab) / length_squared, 0.0, 1.0);
  return norm(p - (a + ab * t));
}

bool contains(const Disc& disc, const Vec2& p) {
  const Vec2 d = p - disc.centre;
  return dot(d, d) <= disc.radius * disc.radius;
}

bool contains(const Capsule& capsule, const Vec2& p) {
  return distance_to_segment(p, capsule.a, capsule.b) <= capsule.radius;
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
    if (distance_to_segment(p, v[j], v[i]) <= kBoundaryTolerance_m) return true;
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
