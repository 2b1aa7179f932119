#pragma once
// The hit-test shapes of the touch primitives, in metres.
#include <vector>

#include "primitives/geometry/box2.hpp"
#include "primitives/geometry/vec2.hpp"

namespace vimg {

struct Disc {  // a DOT
  Vec2 centre;
  double radius = 0.0;
};

struct Capsule {  // a LINE's band: every point within radius of the segment a-b
  Vec2 a;
  Vec2 b;
  double radius = 0.0;
};

struct Rect {  // axis-aligned, min corner and max corner
  Vec2 min;
  Vec2 max;
};

struct Ellipse {  // axis-aligned
  Vec2 centre;
  double rx = 0.0;
  double ry = 0.0;
};

struct Polygon {  // simple or not: even-odd rule; points on the boundary are inside
  std::vector<Vec2> vertices;
};

Box2 bounding_box(const Disc&);
Box2 bounding_box(const Capsule&);
Box2 bounding_box(const Rect&);
Box2 bounding_box(const Ellipse&);
Box2 bounding_box(const Polygon&);

}  // namespace vimg
