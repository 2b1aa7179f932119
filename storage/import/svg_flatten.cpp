#include "storage/import/svg_flatten.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/geometry/hit_test.hpp"

namespace vimg::svg {

namespace {

// Deeper than this the pieces are below 2^-24 of the curve: emitted as they are.
constexpr int kMaxDepth = 24;

bool flat_enough(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 p3, double tolerance) {
  return distance_to_segment(c1, p0, p3) <= tolerance && distance_to_segment(c2, p0, p3) <= tolerance;
}

bool flatten_cubic(Vec2 p0, Vec2 c1, Vec2 c2, Vec2 p3, double tolerance, int depth, std::size_t max_points,
                   std::vector<Vec2>& out) {
  if (depth >= kMaxDepth || flat_enough(p0, c1, c2, p3, tolerance)) {
    if (out.size() >= max_points) return false;
    out.push_back(p3);
    return true;
  }
  const Vec2 a = lerp(p0, c1, 0.5), b = lerp(c1, c2, 0.5), c = lerp(c2, p3, 0.5);
  const Vec2 ab = lerp(a, b, 0.5), bc = lerp(b, c, 0.5), mid = lerp(ab, bc, 0.5);
  return flatten_cubic(p0, a, ab, mid, tolerance, depth + 1, max_points, out) &&
         flatten_cubic(mid, bc, c, p3, tolerance, depth + 1, max_points, out);
}

}  // namespace

bool flatten_subpath(const Subpath& subpath, const Affine& m, double tolerance, std::size_t max_points,
                     std::vector<Vec2>& out) {
  if (out.size() >= max_points) return false;
  Vec2 current = m.apply(subpath.start);
  out.push_back(current);
  for (const PathSegment& s : subpath.segments) {
    const Vec2 end = m.apply(s.end);
    if (s.kind == PathSegment::Kind::line) {
      if (out.size() >= max_points) return false;
      out.push_back(end);
    } else if (!flatten_cubic(current, m.apply(s.c1), m.apply(s.c2), end, tolerance, 0, max_points, out)) {
      return false;
    }
    current = end;
  }
  return true;
}

}  // namespace vimg::svg
