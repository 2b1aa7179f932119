#include "editor/core/polyline_lod.hpp"

namespace vimg::editor {

void decimate_polyline_px(std::span<const Point2Px> in, float min_step_px, bool closed, std::vector<Point2Px>& out) {
  out.clear();
  if (in.empty()) return;
  const float min_step2 = min_step_px * min_step_px;
  out.push_back(in.front());
  for (std::size_t i = 1; i + 1 < in.size(); ++i) {
    const float dx = in[i].x - out.back().x, dy = in[i].y - out.back().y;
    if (dx * dx + dy * dy >= min_step2) out.push_back(in[i]);
  }
  if (in.size() > 1) out.push_back(in.back());
  if (closed && in.size() > 2) out.push_back(in.front());
}

}  // namespace vimg::editor
