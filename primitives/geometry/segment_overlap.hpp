#pragma once
// Where a step p0 -> p1 lies inside a shape, as fractions t of the step (point p0 + t (p1 - p0)).
// This is how shaders place entry and exit inside a sample period instead of at its end.
#include <optional>

#include "primitives/geometry/shapes.hpp"
#include "primitives/geometry/vec2.hpp"

namespace vimg {

struct Interval {  // 0 <= begin <= end <= 1
  double begin = 0.0;
  double end = 0.0;
};

// Convex shapes meet a segment in one interval at most. Analytic (roots or half-plane clipping).
std::optional<Interval> overlap(const Disc& disc, const Vec2& p0, const Vec2& p1);
std::optional<Interval> overlap(const Capsule& capsule, const Vec2& p0, const Vec2& p1);
std::optional<Interval> overlap(const Rect& rect, const Vec2& p0, const Vec2& p1);
std::optional<Interval> overlap(const Ellipse& ellipse, const Vec2& p0, const Vec2& p1);

// A summary that also fits shapes meeting the segment in several intervals (polygons).
struct SegmentOverlap {
  bool any = false;              // some point of the segment is inside
  double first_entry = 0.0;      // start of the first inside interval
  double last_exit = 0.0;        // end of the last inside interval
  double inside_fraction = 0.0;  // total length inside / segment length (0..1)
  bool inside_at_end = false;    // p1 is inside
};

SegmentOverlap summarize(const std::optional<Interval>& interval);
// Exact crossings of every edge, then one robust inside test per piece between crossings.
// Never allocates.
SegmentOverlap overlap_summary(const Polygon& polygon, const Vec2& p0, const Vec2& p1);

}  // namespace vimg
