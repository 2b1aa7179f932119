#include "editor/core/vertex_edit.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::editor {
namespace {

Surface* polygon_of(Element& element) {
  auto* s = std::get_if<Surface>(&element.body);
  return s && s->shape == SurfaceShape::polygon ? s : nullptr;
}
const Surface* polygon_of(const Element& element) {
  const auto* s = std::get_if<Surface>(&element.body);
  return s && s->shape == SurfaceShape::polygon ? s : nullptr;
}

}  // namespace

std::vector<Point2Mm> vertex_points(const Element& element) {
  if (const auto* l = std::get_if<Line>(&element.body)) return {{l->x1_mm, l->y1_mm}, {l->x2_mm, l->y2_mm}};
  if (const Surface* s = polygon_of(element); s && s->points.size() <= kMaxHandleVertices) return s->points;
  return {};
}

std::optional<std::size_t> vertex_at(const Element& element, Point2Mm p, double tolerance_mm) {
  const std::vector<Point2Mm> points = vertex_points(element);
  std::optional<std::size_t> best;
  double best_d = tolerance_mm;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = std::hypot(points[i].x_mm - p.x_mm, points[i].y_mm - p.y_mm);
    if (d <= best_d && (!best || d < best_d)) {
      best = i;
      best_d = d;
    }
  }
  return best;
}

std::optional<EdgeHit> edge_at(const Element& element, Point2Mm p, double tolerance_mm) {
  const Surface* s = polygon_of(element);
  if (!s || s->points.size() < 2 || s->points.size() > kMaxHandleVertices) return std::nullopt;
  const auto& pts = s->points;
  std::optional<EdgeHit> best;
  double best_d = tolerance_mm;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point2Mm a = pts[i];
    const Point2Mm b = pts[(i + 1) % pts.size()];
    const double dx = b.x_mm - a.x_mm, dy = b.y_mm - a.y_mm;
    const double len2 = dx * dx + dy * dy;
    const double t = len2 > 0 ? std::clamp(((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / len2, 0.0, 1.0) : 0.0;
    const Point2Mm foot{a.x_mm + t * dx, a.y_mm + t * dy};
    const double d = std::hypot(p.x_mm - foot.x_mm, p.y_mm - foot.y_mm);
    if (d <= best_d && (!best || d < best_d)) {
      best = EdgeHit{i + 1, foot};
      best_d = d;
    }
  }
  return best;
}

bool move_vertex(Element& element, std::size_t index, Point2Mm to) {
  if (auto* l = std::get_if<Line>(&element.body)) {
    if (index > 1) return false;
    (index == 0 ? l->x1_mm : l->x2_mm) = to.x_mm;
    (index == 0 ? l->y1_mm : l->y2_mm) = to.y_mm;
    return true;
  }
  Surface* s = polygon_of(element);
  if (!s || index >= s->points.size()) return false;
  s->points[index] = to;
  return true;
}

bool insert_vertex(Element& element, const EdgeHit& hit) {
  Surface* s = polygon_of(element);
  if (!s || hit.index > s->points.size()) return false;
  s->points.insert(s->points.begin() + static_cast<std::ptrdiff_t>(hit.index), hit.point);
  return true;
}

bool delete_vertex(Element& element, std::size_t index) {
  Surface* s = polygon_of(element);
  if (!s || index >= s->points.size() || s->points.size() <= kMinPolygonVertices) return false;
  s->points.erase(s->points.begin() + static_cast<std::ptrdiff_t>(index));
  return true;
}

}  // namespace vimg::editor
