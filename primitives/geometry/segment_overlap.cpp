#include "primitives/geometry/segment_overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "primitives/geometry/box2.hpp"
#include "primitives/geometry/hit_test.hpp"

namespace vimg {
namespace {

// Clips t in [lo, hi] by the half-plane n . (p0 + t d) <= c (Liang-Barsky step).
bool clip_half_plane(const Vec2& n, double c, const Vec2& p0, const Vec2& d, double& lo, double& hi) {
  const double start = dot(n, p0);
  const double rate = dot(n, d);
  if (rate == 0.0) return start <= c;
  const double t = (c - start) / rate;
  if (rate > 0.0) {
    hi = std::min(hi, t);
  } else {
    lo = std::max(lo, t);
  }
  return lo <= hi;
}

std::optional<Interval> unit_disc_overlap(const Vec2& p0, const Vec2& p1, double radius) {
  // Solve |p0 + t d|^2 = r^2 with the cancellation-free form of the quadratic roots.
  const Vec2 d = p1 - p0;
  const double a = dot(d, d);
  const double c = dot(p0, p0) - radius * radius;
  if (a == 0.0) {
    if (c <= 0.0) return Interval{0.0, 1.0};
    return std::nullopt;
  }
  const double half_b = dot(d, p0);
  const double discriminant = half_b * half_b - a * c;
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  const double q = -(half_b + std::copysign(root, half_b));
  double t1 = 0.0;
  double t2 = 0.0;
  if (q == 0.0) {
    t1 = t2 = -half_b / a;
  } else {
    t1 = q / a;
    t2 = c / q;
    if (t1 > t2) std::swap(t1, t2);
  }
  const double begin = std::max(t1, 0.0);
  const double end = std::min(t2, 1.0);
  if (begin > end) return std::nullopt;
  return Interval{begin, end};
}

std::optional<Interval> clipped(double lo, double hi) {
  lo = std::max(lo, 0.0);
  hi = std::min(hi, 1.0);
  if (lo > hi) return std::nullopt;
  return Interval{lo, hi};
}

constexpr std::size_t kMaxCrossings = 64;

// Collects the fractions where the segment meets any polygon edge. Returns false if more than
// kMaxCrossings were found (the caller then splits the segment).
bool polygon_crossings(const Polygon& polygon, const Vec2& p0, const Vec2& p1,
                       std::array<double, kMaxCrossings + 2>& out, std::size_t& count) {
  const auto& v = polygon.vertices;
  const std::size_t n = v.size();
  const Vec2 d = p1 - p0;
  const double length = norm(d);
  count = 0;
  auto add = [&](double t) {
    if (!(t >= 0.0 && t <= 1.0)) return true;
    if (count == kMaxCrossings) return false;
    out[count++] = t;
    return true;
  };
  const Box2 step_box = Box2::of_segment(p0, p1).expanded(kBoundaryTolerance_m);
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = v[j];
    if (!step_box.intersects(Box2::of_segment(a, v[i]))) continue;  // cannot meet the step
    const Vec2 e = v[i] - a;
    const double e_length = norm(e);
    const Vec2 w = a - p0;
    const double denominator = cross(d, e);
    if (std::abs(denominator) > 1e-14 * length * e_length) {
      const double t = cross(w, e) / denominator;
      const double s = cross(w, d) / denominator;
      // Accept touching an edge near its ends so paths through vertices are not missed.
      const double slack = e_length > 0.0 ? kBoundaryTolerance_m / e_length : 0.0;
      if (s >= -slack && s <= 1.0 + slack && !add(t)) return false;
    }
    // A parallel edge adds nothing: where the segment runs along an edge, the inside state can
    // only change at the ends of the run, which the neighbouring (non-parallel) edges supply.
  }
  return true;
}

SegmentOverlap combine_halves(const SegmentOverlap& first, const SegmentOverlap& second) {
  SegmentOverlap out;
  out.any = first.any || second.any;
  out.first_entry = first.any ? 0.5 * first.first_entry : 0.5 + 0.5 * second.first_entry;
  out.last_exit = second.any ? 0.5 + 0.5 * second.last_exit : 0.5 * first.last_exit;
  out.inside_fraction = 0.5 * (first.inside_fraction + second.inside_fraction);
  out.inside_at_end = second.inside_at_end;
  return out;
}

}  // namespace

std::optional<Interval> overlap(const Disc& disc, const Vec2& p0, const Vec2& p1) {
  return unit_disc_overlap(p0 - disc.centre, p1 - disc.centre, disc.radius);
}

std::optional<Interval> overlap(const Ellipse& ellipse, const Vec2& p0, const Vec2& p1) {
  if (!(ellipse.rx > 0.0) || !(ellipse.ry > 0.0)) return std::nullopt;
  auto to_unit = [&](const Vec2& p) {
    return Vec2{(p.x - ellipse.centre.x) / ellipse.rx, (p.y - ellipse.centre.y) / ellipse.ry};
  };
  return unit_disc_overlap(to_unit(p0), to_unit(p1), 1.0);
}

std::optional<Interval> overlap(const Rect& rect, const Vec2& p0, const Vec2& p1) {
  const Vec2 d = p1 - p0;
  double lo = 0.0;
  double hi = 1.0;
  if (!clip_half_plane({1, 0}, rect.max.x, p0, d, lo, hi)) return std::nullopt;
  if (!clip_half_plane({-1, 0}, -rect.min.x, p0, d, lo, hi)) return std::nullopt;
  if (!clip_half_plane({0, 1}, rect.max.y, p0, d, lo, hi)) return std::nullopt;
  if (!clip_half_plane({0, -1}, -rect.min.y, p0, d, lo, hi)) return std::nullopt;
  return clipped(lo, hi);
}

std::optional<Interval> overlap(const Capsule& capsule, const Vec2& p0, const Vec2& p1) {
  // A capsule is the union of two discs and a slab; being convex, it meets the segment in one
  // interval, the hull of the three parts' intervals.
  std::optional<Interval> result;
  auto merge = [&](const std::optional<Interval>& part) {
    if (!part) return;
    if (!result) {
      result = part;
    } else {
      result->begin = std::min(result->begin, part->begin);
      result->end = std::max(result->end, part->end);
    }
  };
  merge(overlap(Disc{capsule.a, capsule.radius}, p0, p1));
  merge(overlap(Disc{capsule.b, capsule.radius}, p0, p1));
  const Vec2 axis = capsule.b - capsule.a;
  const double length = norm(axis);
  if (length > 0.0) {
    const Vec2 u = axis * (1.0 / length);
    const Vec2 n{-u.y, u.x};
    const Vec2 d = p1 - p0;
    double lo = 0.0;
    double hi = 1.0;
    const bool hit = clip_half_plane(u, dot(u, capsule.b), p0, d, lo, hi) &&
                     clip_half_plane(u * -1.0, -dot(u, capsule.a), p0, d, lo, hi) &&
                     clip_half_plane(n, dot(n, capsule.a) + capsule.radius, p0, d, lo, hi) &&
                     clip_half_plane(n * -1.0, capsule.radius - dot(n, capsule.a), p0, d, lo, hi);
    if (hit) merge(clipped(lo, hi));
  }
  return result;
}

SegmentOverlap summarize(const std::optional<Interval>& interval) {
  SegmentOverlap out;
  if (!interval) return out;
  out.any = true;
  out.first_entry = interval->begin;
  out.last_exit = interval->end;
  out.inside_fraction = interval->end - interval->begin;
  out.inside_at_end = interval->end >= 1.0;
  return out;
}

SegmentOverlap overlap_summary(const Polygon& polygon, const Vec2& p0, const Vec2& p1) {
  SegmentOverlap out;
  if (polygon.vertices.size() < 3) return out;
  if (p0 == p1) {
    if (contains(polygon, p0)) out = {true, 0.0, 1.0, 1.0, true};
    return out;
  }
  std::array<double, kMaxCrossings + 2> t{};
  std::size_t count = 0;
  if (!polygon_crossings(polygon, p0, p1, t, count)) {
    const Vec2 mid = lerp(p0, p1, 0.5);
    return combine_halves(overlap_summary(polygon, p0, mid), overlap_summary(polygon, mid, p1));
  }
  const std::size_t crossings = count;
  t[count++] = 0.0;
  t[count++] = 1.0;
  std::sort(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(count));
  // Each piece between consecutive crossings is wholly inside or wholly outside.
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const double begin = t[k];
    const double end = t[k + 1];
    const bool inside = end > begin ? contains(polygon, lerp(p0, p1, 0.5 * (begin + end)))
                                    : contains(polygon, lerp(p0, p1, begin));
    if (!inside) continue;
    if (!out.any) {
      out.any = true;
      out.first_entry = begin;
    }
    out.last_exit = end;
    out.inside_fraction += end - begin;
  }
  // Without crossings the segment is wholly in or out, so p1 shares the one piece's answer.
  out.inside_at_end = crossings == 0 ? out.any : contains(polygon, p1);
  if (out.inside_at_end && out.any) out.last_exit = 1.0;
  return out;
}

}  // namespace vimg
