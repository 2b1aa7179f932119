#include "primitives/geometry/shapes.hpp"

#include <algorithm>
#include <limits>

namespace vimg {

Box2 bounding_box(const Disc& disc) {
  const Vec2 r{disc.radius, disc.radius};
  return {disc.centre - r, disc.centre + r};
}

Box2 bounding_box(const Capsule& capsule) {
  return Box2::of_segment(capsule.a, capsule.b).expanded(capsule.radius);
}

Box2 bounding_box(const Rect& rect) { return {rect.min, rect.max}; }

Box2 bounding_box(const Ellipse& ellipse) {
  const Vec2 r{ellipse.rx, ellipse.ry};
  return {ellipse.centre - r, ellipse.centre + r};
}

Box2 bounding_box(const Polygon& polygon) {
  if (polygon.vertices.empty()) return {};
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box2 box{{inf, inf}, {-inf, -inf}};
  for (const Vec2& v : polygon.vertices) {
    box.min = {std::min(box.min.x, v.x), std::min(box.min.y, v.y)};
    box.max = {std::max(box.max.x, v.x), std::max(box.max.y, v.y)};
  }
  return box;
}

}  // namespace vimg
