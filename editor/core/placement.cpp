#include "editor/core/placement.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::editor {

std::optional<Element> place_element(Tool tool, Point2Mm a, Point2Mm b, double px_per_mm) {
  const double dragged_mm = std::hypot(b.x_mm - a.x_mm, b.y_mm - a.y_mm);
  const bool click = dragged_mm * px_per_mm < 3.0;
  Element e;
  switch (tool) {
    case Tool::dot: e.body = Dot{a.x_mm, a.y_mm, click ? 2.0 : dragged_mm, 1.0}; break;
    case Tool::line: {
      Line l;
      l.x1_mm = a.x_mm;
      l.y1_mm = a.y_mm;
      l.x2_mm = click ? a.x_mm + 20.0 : b.x_mm;
      l.y2_mm = click ? a.y_mm : b.y_mm;
      e.body = l;
      break;
    }
    case Tool::rect: {
      Surface s;
      s.shape = SurfaceShape::rect;
      const RectMm r = click ? RectMm{a.x_mm, a.y_mm, a.x_mm + 20, a.y_mm + 20} : rect_from_corners(a, b);
      s.x_mm = r.x0_mm;
      s.y_mm = r.y0_mm;
      s.width_mm = std::max(0.1, r.width_mm());
      s.height_mm = std::max(0.1, r.height_mm());
      e.body = s;
      break;
    }
    case Tool::ellipse: {
      Surface s;
      s.shape = SurfaceShape::ellipse;
      const RectMm r = click ? RectMm{a.x_mm - 10, a.y_mm - 10, a.x_mm + 10, a.y_mm + 10} : rect_from_corners(a, b);
      s.cx_mm = (r.x0_mm + r.x1_mm) / 2;
      s.cy_mm = (r.y0_mm + r.y1_mm) / 2;
      s.rx_mm = std::max(0.05, r.width_mm() / 2);
      s.ry_mm = std::max(0.05, r.height_mm() / 2);
      e.body = s;
      break;
    }
    default: return std::nullopt;
  }
  return e;
}

std::optional<Element> polygon_element(const std::vector<Point2Mm>& points) {
  if (points.size() < 3) return std::nullopt;
  Surface s;
  s.shape = SurfaceShape::polygon;
  s.points = points;
  Element e;
  e.body = std::move(s);
  return e;
}

Point2Mm handle_position(const RectMm& box, int handle) {
  const std::size_t i = static_cast<std::size_t>(std::clamp(handle, 0, 7));
  const double xs[3] = {box.x0_mm, (box.x0_mm + box.x1_mm) / 2, box.x1_mm};
  const double ys[3] = {box.y0_mm, (box.y0_mm + box.y1_mm) / 2, box.y1_mm};
  return Point2Mm{xs[kHandleColumn[i]], ys[kHandleRow[i]]};
}

RectMm resized_box(const RectMm& from, int handle, double dx_mm, double dy_mm, double snap_step_mm) {
  const std::size_t i = static_cast<std::size_t>(std::clamp(handle, 0, 7));
  const double dx = snap_mm(dx_mm, snap_step_mm);
  const double dy = snap_mm(dy_mm, snap_step_mm);
  RectMm r = from;
  if (kHandleColumn[i] == 0) r.x0_mm = std::min(from.x0_mm + dx, from.x1_mm - kMinResizedSideMm);
  if (kHandleColumn[i] == 2) r.x1_mm = std::max(from.x1_mm + dx, from.x0_mm + kMinResizedSideMm);
  if (kHandleRow[i] == 0) r.y0_mm = std::min(from.y0_mm + dy, from.y1_mm - kMinResizedSideMm);
  if (kHandleRow[i] == 2) r.y1_mm = std::max(from.y1_mm + dy, from.y0_mm + kMinResizedSideMm);
  return r;
}

}  // namespace vimg::editor
