#pragma once
// Axis-aligned 2D boxes in metres (x right, y down): primitive extents and query regions.
#include <algorithm>

#include "primitives/vec3.hpp"

namespace vimg {

struct Bounds2M {
  double min_x_m = 0.0;
  double min_y_m = 0.0;
  double max_x_m = 0.0;
  double max_y_m = 0.0;

  // The box spanned by a step from a to b (the segment a finger swept during one sample).
  static constexpr Bounds2M of_segment(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
  }
  constexpr bool intersects(const Bounds2M& o) const {
    return min_x_m <= o.max_x_m && o.min_x_m <= max_x_m && min_y_m <= o.max_y_m && o.min_y_m <= max_y_m;
  }
  constexpr Bounds2M united(const Bounds2M& o) const {
    return {std::min(min_x_m, o.min_x_m), std::min(min_y_m, o.min_y_m), std::max(max_x_m, o.max_x_m),
            std::max(max_y_m, o.max_y_m)};
  }
};

}  // namespace vimg
