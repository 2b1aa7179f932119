#include "editor/core/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace vimg::editor {
namespace {

constexpr double kMinSizeMm = 0.05;

std::optional<RectMm> surface_bounds(const Surface& s) {
  switch (s.shape) {
    case SurfaceShape::rect:
      return RectMm{s.x_mm, s.y_mm, s.x_mm + s.width_mm, s.y_mm + s.height_mm};
    case SurfaceShape::ellipse:
      return RectMm{s.cx_mm - s.rx_mm, s.cy_mm - s.ry_mm, s.cx_mm + s.rx_mm, s.cy_mm + s.ry_mm};
    case SurfaceShape::polygon: {
      if (s.points.empty()) return std::nullopt;
      RectMm r{s.points[0].x_mm, s.points[0].y_mm, s.points[0].x_mm, s.points[0].y_mm};
      for (const Point2Mm& p : s.points) r = united(r, RectMm{p.x_mm, p.y_mm, p.x_mm, p.y_mm});
      return r;
    }
  }
  return std::nullopt;
}

bool polygon_contains(const std::vector<Point2Mm>& pts, Point2Mm p) {
  bool inside = false;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const Point2Mm& a = pts[i];
    const Point2Mm& b = pts[j];
    if ((a.y_mm > p.y_mm) != (b.y_mm > p.y_mm) &&
        p.x_mm < (b.x_mm - a.x_mm) * (p.y_mm - a.y_mm) / (b.y_mm - a.y_mm) + a.x_mm) {
      inside = !inside;
    }
  }
  return inside;
}

bool surface_contains(const Surface& s, Point2Mm p, double tol) {
  switch (s.shape) {
    case SurfaceShape::rect:
      return p.x_mm >= s.x_mm - tol && p.x_mm <= s.x_mm + s.width_mm + tol && p.y_mm >= s.y_mm - tol &&
             p.y_mm <= s.y_mm + s.height_mm + tol;
    case SurfaceShape::ellipse: {
      const double rx = s.rx_mm + tol;
      const double ry = s.ry_mm + tol;
      if (rx <= 0 || ry <= 0) return false;
      const double u = (p.x_mm - s.cx_mm) / rx;
      const double v = (p.y_mm - s.cy_mm) / ry;
      return u * u + v * v <= 1.0;
    }
    case SurfaceShape::polygon:
      if (s.points.size() < 3) return false;
      if (polygon_contains(s.points, p)) return true;
      // On the outline within the slack (the rect and ellipse grow by it too).
      for (std::size_t i = 0, j = s.points.size() - 1; tol > 0 && i < s.points.size(); j = i++) {
        if (distance_to_segment_mm(p, s.points[j], s.points[i]) <= tol) return true;
      }
      return false;
  }
  return false;
}

double map_x(double x, const RectMm& from, const RectMm& to) {
  const double w = from.width_mm();
  if (w <= 0) return to.x0_mm + (x - from.x0_mm);
  return to.x0_mm + (x - from.x0_mm) * to.width_mm() / w;
}

double map_y(double y, const RectMm& from, const RectMm& to) {
  const double h = from.height_mm();
  if (h <= 0) return to.y0_mm + (y - from.y0_mm);
  return to.y0_mm + (y - from.y0_mm) * to.height_mm() / h;
}

double mean_factor(const RectMm& from, const RectMm& to) {
  const double fx = from.width_mm() > 0 ? to.width_mm() / from.width_mm() : 1.0;
  const double fy = from.height_mm() > 0 ? to.height_mm() / from.height_mm() : 1.0;
  return 0.5 * (fx + fy);
}

}  // namespace

RectMm rect_from_corners(Point2Mm a, Point2Mm b) {
  return RectMm{std::min(a.x_mm, b.x_mm), std::min(a.y_mm, b.y_mm), std::max(a.x_mm, b.x_mm),
                std::max(a.y_mm, b.y_mm)};
}

RectMm united(const RectMm& a, const RectMm& b) {
  return RectMm{std::min(a.x0_mm, b.x0_mm), std::min(a.y0_mm, b.y0_mm), std::max(a.x1_mm, b.x1_mm),
                std::max(a.y1_mm, b.y1_mm)};
}

double distance_to_segment_mm(Point2Mm p, Point2Mm a, Point2Mm b) {
  const double dx = b.x_mm - a.x_mm;
  const double dy = b.y_mm - a.y_mm;
  const double len2 = dx * dx + dy * dy;
  double t = 0.0;
  if (len2 > 0) t = std::clamp(((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / len2, 0.0, 1.0);
  return std::hypot(p.x_mm - (a.x_mm + t * dx), p.y_mm - (a.y_mm + t * dy));
}

std::optional<RectMm> element_bounds(const Element& element) {
  if (const auto* d = std::get_if<Dot>(&element.body)) {
    return RectMm{d->x_mm - d->radius_mm, d->y_mm - d->radius_mm, d->x_mm + d->radius_mm, d->y_mm + d->radius_mm};
  }
  if (const auto* l = std::get_if<Line>(&element.body)) {
    const double h = l->width_mm / 2;
    return RectMm{std::min(l->x1_mm, l->x2_mm) - h, std::min(l->y1_mm, l->y2_mm) - h,
                  std::max(l->x1_mm, l->x2_mm) + h, std::max(l->y1_mm, l->y2_mm) + h};
  }
  if (const auto* s = std::get_if<Surface>(&element.body)) return surface_bounds(*s);
  if (const auto* g = std::get_if<Group>(&element.body)) {
    std::optional<RectMm> r;
    for (const Element& c : g->children) {
      if (auto b = element_bounds(c)) r = r ? united(*r, *b) : *b;
    }
    return r;
  }
  return std::nullopt;
}

bool element_contains(const Element& element, Point2Mm p, double tol) {
  if (const auto* d = std::get_if<Dot>(&element.body)) {
    return std::hypot(p.x_mm - d->x_mm, p.y_mm - d->y_mm) <= d->radius_mm + tol;
  }
  if (const auto* l = std::get_if<Line>(&element.body)) {
    return distance_to_segment_mm(p, {l->x1_mm, l->y1_mm}, {l->x2_mm, l->y2_mm}) <= l->width_mm / 2 + tol;
  }
  if (const auto* s = std::get_if<Surface>(&element.body)) return surface_contains(*s, p, tol);
  if (const auto* g = std::get_if<Group>(&element.body)) {
    return std::any_of(g->children.begin(), g->children.end(),
                       [&](const Element& c) { return element_contains(c, p, tol); });
  }
  return false;
}

void translate_element(Element& element, double dx, double dy) {
  if (auto* d = std::get_if<Dot>(&element.body)) {
    d->x_mm += dx;
    d->y_mm += dy;
  } else if (auto* l = std::get_if<Line>(&element.body)) {
    l->x1_mm += dx;
    l->y1_mm += dy;
    l->x2_mm += dx;
    l->y2_mm += dy;
  } else if (auto* s = std::get_if<Surface>(&element.body)) {
    if (s->shape == SurfaceShape::rect) {
      s->x_mm += dx;
      s->y_mm += dy;
    } else if (s->shape == SurfaceShape::ellipse) {
      s->cx_mm += dx;
      s->cy_mm += dy;
    }
    for (Point2Mm& p : s->points) {
      p.x_mm += dx;
      p.y_mm += dy;
    }
  } else if (auto* g = std::get_if<Group>(&element.body)) {
    for (Element& c : g->children) translate_element(c, dx, dy);
  }
}

void map_element(Element& element, const RectMm& from, const RectMm& to) {
  const double f = mean_factor(from, to);
  if (auto* d = std::get_if<Dot>(&element.body)) {
    d->x_mm = map_x(d->x_mm, from, to);
    d->y_mm = map_y(d->y_mm, from, to);
    d->radius_mm = std::max(kMinSizeMm, d->radius_mm * f);
  } else if (auto* l = std::get_if<Line>(&element.body)) {
    // The bounds include the band: map the segment inside the band-less rectangles.
    const double h = l->width_mm / 2;
    const RectMm inner_from{from.x0_mm + h, from.y0_mm + h, from.x1_mm - h, from.y1_mm - h};
    const RectMm inner_to{to.x0_mm + h, to.y0_mm + h, std::max(to.x0_mm + h, to.x1_mm - h),
                          std::max(to.y0_mm + h, to.y1_mm - h)};
    l->x1_mm = map_x(l->x1_mm, inner_from, inner_to);
    l->x2_mm = map_x(l->x2_mm, inner_from, inner_to);
    l->y1_mm = map_y(l->y1_mm, inner_from, inner_to);
    l->y2_mm = map_y(l->y2_mm, inner_from, inner_to);
  } else if (auto* s = std::get_if<Surface>(&element.body)) {
    if (s->shape == SurfaceShape::rect) {
      const double x0 = map_x(s->x_mm, from, to);
      const double y0 = map_y(s->y_mm, from, to);
      const double x1 = map_x(s->x_mm + s->width_mm, from, to);
      const double y1 = map_y(s->y_mm + s->height_mm, from, to);
      s->x_mm = x0;
      s->y_mm = y0;
      s->width_mm = std::max(kMinSizeMm, x1 - x0);
      s->height_mm = std::max(kMinSizeMm, y1 - y0);
    } else if (s->shape == SurfaceShape::ellipse) {
      const double fx = from.width_mm() > 0 ? to.width_mm() / from.width_mm() : 1.0;
      const double fy = from.height_mm() > 0 ? to.height_mm() / from.height_mm() : 1.0;
      s->cx_mm = map_x(s->cx_mm, from, to);
      s->cy_mm = map_y(s->cy_mm, from, to);
      s->rx_mm = std::max(kMinSizeMm, s->rx_mm * fx);
      s->ry_mm = std::max(kMinSizeMm, s->ry_mm * fy);
    } else {
      for (Point2Mm& p : s->points) {
        p.x_mm = map_x(p.x_mm, from, to);
        p.y_mm = map_y(p.y_mm, from, to);
      }
    }
  } else if (auto* g = std::get_if<Group>(&element.body)) {
    for (Element& c : g->children) map_element(c, from, to);
  }
}

double snap_mm(double value_mm, double step_mm) {
  if (step_mm <= 0) return value_mm;
  return std::round(value_mm / step_mm) * step_mm;
}

}  // namespace vimg::editor
