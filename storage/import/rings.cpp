#include "storage/import/rings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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

namespace {

// The vertex of `outer` nearest to `p` (the lowest index among equally near ones), searched in
// `by_x` (outer's indices sorted by x) outwards from p.x until |dx| alone is farther than the best:
// O(log n) plus the vertices within that band. Each vertex looked at costs one unit of `work`.
std::size_t nearest_vertex(const Ring& outer, const std::vector<std::size_t>& by_x, bool ordered, Vec2 p,
                           std::size_t& work) {
  const auto start = ordered ? std::lower_bound(by_x.begin(), by_x.end(), p.x,
                                                [&](std::size_t i, double x) { return outer[i].x < x; })
                             : by_x.begin();
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  const auto consider = [&](std::size_t i) {
    ++work;
    const Vec2 d = outer[i] - p;
    const double distance = dot(d, d);
    if (distance < best_distance || (distance == best_distance && i < best)) {
      best_distance = distance;
      best = i;
    }
  };
  const auto beyond = [&](std::size_t i) {
    if (!ordered) return false;
    const double dx = outer[i].x - p.x;
    return dx * dx > best_distance;
  };
  for (auto it = start; it != by_x.end() && !beyond(*it); ++it) consider(*it);
  for (auto it = start; it != by_x.begin() && !beyond(*(it - 1)); --it) consider(*(it - 1));
  return best;
}

}  // namespace

Ring bridge_rings(const std::vector<Ring>& rings) {
  std::size_t work = 0;
  return *bridge_rings(rings, std::numeric_limits<std::size_t>::max(), work);
}

std::optional<Ring> bridge_rings(const std::vector<Ring>& rings, std::size_t max_work, std::size_t& work) {
  if (rings.empty()) return Ring{};
  const Ring& outer = rings.front();
  // For each vertex of the first ring, the rings bridged from it.
  std::vector<std::vector<std::size_t>> attached(outer.size());
  // Sorted by x; with a NaN among them (no order), left unsorted and searched whole.
  std::vector<std::size_t> by_x(outer.size());
  std::iota(by_x.begin(), by_x.end(), std::size_t{0});
  const bool ordered = std::none_of(outer.begin(), outer.end(), [](Vec2 v) { return std::isnan(v.x); });
  if (ordered) std::sort(by_x.begin(), by_x.end(), [&](std::size_t i, std::size_t j) { return outer[i].x < outer[j].x; });
  work += outer.size();
  for (std::size_t r = 1; r < rings.size(); ++r) {
    if (work > max_work) return std::nullopt;
    attached[nearest_vertex(outer, by_x, ordered, rings[r].front(), work)].push_back(r);
  }
  if (work > max_work) return std::nullopt;
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
