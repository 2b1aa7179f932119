#pragma once
// Point-in-shape tests. Points on the boundary count as inside for every shape.
#include "primitives/geometry/shapes.hpp"
#include "primitives/geometry/vec2.hpp"

namespace vimg {

// Distance tolerance (m) within which a point counts as on a polygon's boundary. Far below a
// screen pixel, far above the rounding of millimetre coordinates converted to metres.
inline constexpr double kBoundaryTolerance_m = 1e-12;

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b);

bool contains(const Disc& disc, const Vec2& p);
bool contains(const Capsule& capsule, const Vec2& p);
bool contains(const Rect& rect, const Vec2& p);
bool contains(const Ellipse& ellipse, const Vec2& p);
bool contains(const Polygon& polygon, const Vec2& p);

}  // namespace vimg
