#pragma once
// Outlines as the screen can show them. A polygon of 250 000 points drawn as is overflows the
// stack inside Dear ImGui's stroke code (it allocates its normals with alloca) and costs far more
// than the pixels it covers. Points closer than `min_step_px` to the last kept point are dropped
// (the first and last are always kept), and strokes are issued in runs of at most kMaxRunPoints.
#include <cstddef>
#include <span>
#include <vector>

#include "editor/core/viewport.hpp"

namespace vimg::editor {

inline constexpr std::size_t kMaxRunPoints = 1024;

// Appends the kept points of `in` to `out` (cleared first). For a closed outline pass the points
// once; `closed` appends the first point at the end so that runs of an open stroke close it.
void decimate_polyline_px(std::span<const Point2Px> in, float min_step_px, bool closed, std::vector<Point2Px>& out);

// Calls draw(first, count) for consecutive runs of at most kMaxRunPoints points that together
// trace `points` (each run starts at the last point of the previous one).
template <class Draw>
void for_each_stroke_run(std::span<const Point2Px> points, Draw&& draw) {
  if (points.size() < 2) return;
  for (std::size_t start = 0; start + 1 < points.size(); start += kMaxRunPoints - 1) {
    const std::size_t count = std::min(kMaxRunPoints, points.size() - start);
    draw(points.data() + start, count);
  }
}

}  // namespace vimg::editor
