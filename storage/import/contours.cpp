#include "storage/import/contours.hpp"

#include <unordered_map>
#include <utility>

#include "primitives/geometry/hit_test.hpp"

namespace vimg::import {

namespace {

// Crossing ids: horizontal sample pairs (i,j)-(i+1,j) first, then vertical pairs (i,j)-(i,j+1),
// on the padded sample grid of (width+2) x (height+2) samples.
struct Grid {
  std::int64_t w;  // padded width (samples)
  std::int64_t h;  // padded height
  std::int64_t horizontal(std::int64_t i, std::int64_t j) const { return j * w + i; }
  std::int64_t vertical(std::int64_t i, std::int64_t j) const { return w * h + j * w + i; }
  Vec2 point(std::int64_t id) const {
    if (id < w * h) return {static_cast<double>(id % w), static_cast<double>(id / w) - 0.5};
    id -= w * h;
    return {static_cast<double>(id % w) - 0.5, static_cast<double>(id / w)};
  }
};

}  // namespace

std::vector<Ring> trace_contours(const std::vector<std::uint8_t>& mask, int width, int height) {
  const Grid grid{width + 2, height + 2};
  const auto sample = [&](std::int64_t i, std::int64_t j) -> bool {
    if (i < 1 || j < 1 || i > width || j > height) return false;
    return mask[static_cast<std::size_t>((j - 1) * width + (i - 1))] != 0;
  };
  std::unordered_map<std::int64_t, std::int64_t> next;  // segment start crossing -> end crossing
  for (std::int64_t j = 0; j + 1 < grid.h; ++j) {
    for (std::int64_t i = 0; i + 1 < grid.w; ++i) {
      // Corners clockwise on screen: top-left, top-right, bottom-right, bottom-left; the edge k
      // runs from corner k to corner k+1.
      const bool c[4] = {sample(i, j), sample(i + 1, j), sample(i + 1, j + 1), sample(i, j + 1)};
      if (c[0] == c[1] && c[1] == c[2] && c[2] == c[3]) continue;
      const std::int64_t edge[4] = {grid.horizontal(i, j), grid.vertical(i + 1, j), grid.horizontal(i, j + 1),
                                    grid.vertical(i, j)};
      // Pair each crossing into the set (out -> in, clockwise) with the next crossing out of it:
      // set corners that touch only diagonally stay apart.
      for (int k = 0; k < 4; ++k) {
        if (c[k] || !c[(k + 1) % 4]) continue;
        int m = (k + 1) % 4;
        while (!(c[m] && !c[(m + 1) % 4])) m = (m + 1) % 4;
        next.emplace(edge[k], edge[m]);
      }
    }
  }
  std::vector<Ring> rings;
  while (!next.empty()) {
    const std::int64_t first = next.begin()->first;
    Ring ring;
    std::int64_t at = first;
    while (true) {
      const auto it = next.find(at);
      if (it == next.end()) break;
      ring.push_back(grid.point(at));
      at = it->second;
      next.erase(it);
    }
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  return rings;
}

Ring simplify_ring(const Ring& ring, double tolerance) {
  const std::size_t n = ring.size();
  if (n < 4) return ring;
  std::size_t far = 0;
  double far_distance = -1.0;
  for (std::size_t i = 1; i < n; ++i) {
    const Vec2 d = ring[i] - ring[0];
    if (dot(d, d) > far_distance) {
      far_distance = dot(d, d);
      far = i;
    }
  }
  std::vector<bool> keep(n, false);
  keep[0] = keep[far] = true;
  // Spans [a, b] of ring indices (b may pass n: indices are taken modulo n).
  std::vector<std::pair<std::size_t, std::size_t>> spans = {{0, far}, {far, n}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    const Vec2 pa = ring[a % n], pb = ring[b % n];
    std::size_t worst = a;
    double worst_distance = tolerance;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = distance_to_segment(ring[i % n], pa, pb);
      if (d > worst_distance) {
        worst_distance = d;
        worst = i;
      }
    }
    if (worst == a) continue;
    keep[worst % n] = true;
    spans.push_back({a, worst});
    spans.push_back({worst, b});
  }
  Ring out;
  for (std::size_t i = 0; i < n; ++i) {
    if (keep[i]) out.push_back(ring[i]);
  }
  return out;
}

}  // namespace vimg::import
