#pragma once
// Axis-aligned bounding box in metres, for the player's broad phase (which contacts to create).
#include <algorithm>

#include "primitives/geometry/vec2.hpp"

namespace vimg {

struct Box2 {
  Vec2 min;
  Vec2 max;

  constexpr bool contains(const Vec2& p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
  }
  constexpr Box2 expanded(double margin_m) const {
    return {{min.x - margin_m, min.y - margin_m}, {max.x + margin_m, max.y + margin_m}};
  }
  constexpr bool intersects(const Box2& o) const {
    return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y;
  }
  // The box of the segment a -> b (a finger's step).
  static constexpr Box2 of_segment(const Vec2& a, const Vec2& b) {
    return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
  }
};

}  // namespace vimg
