#pragma once
// Outlines of a binary mask (marching squares) and their simplification (Douglas-Peucker).
// Samples sit at pixel centres and the mask is taken as 0 outside the picture, so every outline is
// a closed ring through the midpoints of pixel edges (coordinates in pixels, x right, y down, the
// picture's top-left corner at 0,0). Where two set pixels touch only at a corner (a saddle), they
// are kept apart, for every mask alike. Rings keep the set pixels on their left as seen on screen:
// outer outlines have twice_signed_area() < 0 in these coordinates, holes > 0. Pure: no I/O.
//
// Cost: tracing visits each sample pair once (linear in pixels, one bit of memory per pair);
// simplification is linear in a ring's points whatever their shape, and works as they arrive. Both
// count their work, so that tests can check how it grows without timing it.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "storage/import/rings.hpp"

namespace vimg::import {

struct TraceStats {
  std::size_t pairs_scanned = 0;      // horizontal sample pairs looked at for the start of an outline
  std::size_t crossings_visited = 0;  // outline points made (each crossing once)
  std::size_t rings = 0;              // outlines finished
  bool stopped = false;               // the caller asked to stop
};

// Walks every outline point by point, in raster order of its topmost row (so an outline comes
// before every hole inside it): on_point(p) for each of its points, then on_end(). Stops as soon as
// either returns false, so that a caller can refuse an outline before it is whole. `mask` has
// width * height entries, rows top to bottom; non-zero is set.
TraceStats walk_contours(const std::vector<std::uint8_t>& mask, int width, int height,
                         const std::function<bool(Vec2)>& on_point, const std::function<bool()>& on_end);

// Calls on_ring(ring) for each whole outline (walk_contours), until on_ring returns false.
TraceStats for_each_contour(const std::vector<std::uint8_t>& mask, int width, int height,
                            const std::function<bool(Ring&)>& on_ring);

// Every outline of the mask (for_each_contour, collected).
std::vector<Ring> trace_contours(const std::vector<std::uint8_t>& mask, int width, int height);

struct SimplifyStats {
  std::size_t distance_tests = 0;  // point-to-segment distances computed
};

// A closed ring simplified as its points arrive, so that every dropped point lies within
// `tolerance` of the kept outline. A point on the straight line between its neighbours goes at
// once; the rest are held in windows of kWindowPoints, each simplified by Douglas-Peucker between
// its ends (kept), splitting a span at its farthest point, or at its middle when that point lies
// in the span's outer quarters. A ring shorter than a window is thus anchored at its first point and
// the point farthest from it. Memory is the points kept and one window; the cost is linear in the
// points given, and kept() tells the caller, while the ring is still arriving, how many it keeps.
class RingSimplifier {
 public:
  static constexpr std::size_t kWindowPoints = 16384;
  explicit RingSimplifier(double tolerance, SimplifyStats* stats = nullptr) : tolerance_(tolerance), stats_(stats) {}
  void add(Vec2 p);
  std::size_t kept() const { return kept_.size(); }  // kept so far, before the open window
  // The simplified ring; the simplifier is ready for the next ring.
  Ring finish();

 private:
  void simplify_window();
  double tolerance_;
  SimplifyStats* stats_;
  Ring kept_;
  Ring window_;  // from the last kept point (or the first point) on
};

// The whole ring through a RingSimplifier.
Ring simplify_ring(const Ring& ring, double tolerance, SimplifyStats* stats = nullptr);

}  // namespace vimg::import
