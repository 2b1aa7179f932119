#include "storage/import/rings.hpp"

#include <limits>

namespace vimg::import {

double twice_signed_area(const Ring& ring) {
  double sum = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) sum += cross(ring[i], ring[(i + 1) % n]);
  return sum;
}

void remove_repeats(Ring& ring, bool closed) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (kept > 0 && ring[i] == ring[kept - 1]) continue;
    ring[kept++] = ring[i];
  }
  ring.resize(kept);
  while (closed && ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
}

Ring bridge_rings(const std::vector<Ring>& rings) {
  if (rings.empty()) return {};
  const Ring& outer = rings.front();
  // For each vertex of the first ring, the rings bridged from it.
  std::vector<std::vector<std::size_t>> attached(outer.size());
  for (std::size_t r = 1; r < rings.size(); ++r) {
    const Vec2 h0 = rings[r].front();
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < outer.size(); ++i) {
      const Vec2 d = outer[i] - h0;
      if (dot(d, d) < best_distance) {
        best_distance = dot(d, d);
        best = i;
      }
    }
    attached[best].push_back(r);
  }
  Ring out;
  std::size_t total = outer.size();
  for (std::size_t r = 1; r < rings.size(); ++r) total += rings[r].size() + 2;
  out.reserve(total);
  for (std::size_t i = 0; i < outer.size(); ++i) {
    out.push_back(outer[i]);
    for (const std::size_t r : attached[i]) {
      out.insert(out.end(), rings[r].begin(), rings[r].end());
      out.push_back(rings[r].front());
      out.push_back(outer[i]);
    }
  }
  return out;
}

}  // namespace vimg::import
