#include "storage/import/contours.hpp"

#include <utility>

#include "primitives/geometry/hit_test.hpp"

namespace vimg::import {

namespace {

// The padded sample grid of (width+2) x (height+2) samples, and the crossings of an outline through
// it. Crossing ids: horizontal sample pairs (i,j)-(i+1,j) first, then vertical pairs (i,j)-(i,j+1).
class Grid {
 public:
  Grid(const std::vector<std::uint8_t>& mask, int width, int height)
      : mask_(mask), width_(width), height_(height), w_(width + 2), h_(height + 2) {}

  std::int64_t horizontal_pairs() const { return w_ * h_; }
  std::int64_t crossings() const { return 2 * w_ * h_; }

  bool sample(std::int64_t i, std::int64_t j) const {
    if (i < 1 || j < 1 || i > width_ || j > height_) return false;
    return mask_[static_cast<std::size_t>((j - 1) * width_ + (i - 1))] != 0;
  }

  // A horizontal pair that an outline crosses (its two samples differ).
  bool crossed(std::int64_t id) const {
    const std::int64_t i = id % w_, j = id / w_;
    return i + 1 < w_ && sample(i, j) != sample(i + 1, j);
  }

  Vec2 point(std::int64_t id) const {
    if (id < w_ * h_) return {static_cast<double>(id % w_), static_cast<double>(id / w_) - 0.5};
    id -= w_ * h_;
    return {static_cast<double>(id % w_) - 0.5, static_cast<double>(id / w_)};
  }

  // The crossing after `id` on its outline. Each crossing starts a segment in exactly one of the two
  // cells it borders: the one whose clockwise walk goes from an unset to a set sample across it.
  std::int64_t next(std::int64_t id) const {
    std::int64_t ci = 0, cj = 0;
    int k = 0;  // the edge of cell (ci, cj) the crossing lies on
    if (id < w_ * h_) {
      const std::int64_t i = id % w_, j = id / w_;
      if (!sample(i, j) && sample(i + 1, j)) {
        ci = i, cj = j, k = 0;  // the top edge of the cell below
      } else {
        ci = i, cj = j - 1, k = 2;  // the bottom edge of the cell above
      }
    } else {
      const std::int64_t i = (id - w_ * h_) % w_, j = (id - w_ * h_) / w_;
      if (!sample(i, j) && sample(i, j + 1)) {
        ci = i - 1, cj = j, k = 1;  // the right edge of the cell on the left
      } else {
        ci = i, cj = j, k = 3;  // the left edge of the cell on the right
      }
    }
    // Corners clockwise on screen: top-left, top-right, bottom-right, bottom-left; the edge k
    // runs from corner k to corner k+1. The segment leaves by the next edge, clockwise, that goes
    // from a set to an unset corner: set corners that touch only diagonally stay apart.
    const bool c[4] = {sample(ci, cj), sample(ci + 1, cj), sample(ci + 1, cj + 1), sample(ci, cj + 1)};
    const std::int64_t edge[4] = {horizontal(ci, cj), vertical(ci + 1, cj), horizontal(ci, cj + 1), vertical(ci, cj)};
    int m = (k + 1) % 4;
    while (!(c[m] && !c[(m + 1) % 4])) m = (m + 1) % 4;
    return edge[m];
  }

 private:
  std::int64_t horizontal(std::int64_t i, std::int64_t j) const { return j * w_ + i; }
  std::int64_t vertical(std::int64_t i, std::int64_t j) const { return w_ * h_ + j * w_ + i; }

  const std::vector<std::uint8_t>& mask_;
  std::int64_t width_, height_;
  std::int64_t w_, h_;  // padded
};

// Whether `p` lies on the straight line from `before` to `after`, between them.
bool straight_between(Vec2 before, Vec2 p, Vec2 after) {
  const Vec2 in = p - before, on = after - p;
  return cross(in, on) == 0.0 && dot(in, on) > 0.0;
}

}  // namespace

TraceStats walk_contours(const std::vector<std::uint8_t>& mask, int width, int height,
                         const std::function<bool(Vec2)>& on_point, const std::function<bool()>& on_end) {
  const Grid grid(mask, width, height);
  std::vector<bool> visited(static_cast<std::size_t>(grid.crossings()), false);
  TraceStats stats;
  // Every outline crosses some horizontal pair; its first one in raster order starts it.
  for (std::int64_t first = 0; first < grid.horizontal_pairs(); ++first) {
    ++stats.pairs_scanned;
    if (visited[static_cast<std::size_t>(first)] || !grid.crossed(first)) continue;
    std::int64_t at = first;
    do {
      visited[static_cast<std::size_t>(at)] = true;
      ++stats.crossings_visited;
      if (!on_point(grid.point(at))) {
        stats.stopped = true;
        return stats;
      }
      at = grid.next(at);
    } while (at != first);
    ++stats.rings;
    if (!on_end()) {
      stats.stopped = true;
      return stats;
    }
  }
  return stats;
}

TraceStats for_each_contour(const std::vector<std::uint8_t>& mask, int width, int height,
                            const std::function<bool(Ring&)>& on_ring) {
  Ring ring;
  return walk_contours(
      mask, width, height,
      [&ring](Vec2 p) {
        ring.push_back(p);
        return true;
      },
      [&] {
        Ring whole = std::move(ring);
        ring.clear();
        return whole.size() < 3 || on_ring(whole);
      });
}

std::vector<Ring> trace_contours(const std::vector<std::uint8_t>& mask, int width, int height) {
  std::vector<Ring> rings;
  for_each_contour(mask, width, height, [&rings](Ring& ring) {
    rings.push_back(std::move(ring));
    return true;
  });
  return rings;
}

void RingSimplifier::add(Vec2 p) {
  // The window's first point is kept; a later last point on the straight way to `p` goes.
  if (window_.size() >= 2 && straight_between(window_[window_.size() - 2], window_.back(), p)) window_.pop_back();
  window_.push_back(p);
  if (window_.size() >= kWindowPoints) simplify_window();
}

void RingSimplifier::simplify_window() {
  const std::size_t n = window_.size();
  std::vector<bool> keep(n, false);
  keep[0] = keep[n - 1] = true;
  std::size_t tests = 0;
  std::vector<std::pair<std::size_t, std::size_t>> spans = {{0, n - 1}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    std::size_t worst = a;
    double worst_distance = tolerance_;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double d = distance_to_segment(window_[i], window_[a], window_[b]);
      if (d > worst_distance) {
        worst_distance = d;
        worst = i;
      }
    }
    tests += b > a ? b - a - 1 : 0;
    if (worst == a) continue;
    const std::size_t quarter = (b - a) / 4;
    const std::size_t split = (worst - a < quarter || b - worst < quarter) ? a + (b - a) / 2 : worst;
    keep[split] = true;
    spans.push_back({a, split});
    spans.push_back({split, b});
  }
  if (stats_ != nullptr) stats_->distance_tests += tests;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (keep[i]) kept_.push_back(window_[i]);
  }
  const Vec2 last = window_[n - 1];
  window_.clear();
  window_.push_back(last);
}

Ring RingSimplifier::finish() {
  if (!window_.empty() || !kept_.empty()) {
    // Closed: the first point again ends the last window (and is dropped as a repeat).
    add(kept_.empty() ? window_.front() : kept_.front());
    if (window_.size() >= 2) simplify_window();
  }
  window_.clear();
  Ring ring = std::move(kept_);
  kept_.clear();
  return ring;
}

Ring simplify_ring(const Ring& ring, double tolerance, SimplifyStats* stats) {
  RingSimplifier simplifier(tolerance, stats);
  for (const Vec2& p : ring) simplifier.add(p);
  return simplifier.finish();
}

}  // namespace vimg::import
