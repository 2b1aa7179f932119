#include "storage/import/svg_shapes.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "primitives/geometry/hit_test.hpp"
#include "storage/import/rings.hpp"
#include "storage/import/svg_flatten.hpp"
#include "storage/limits.hpp"

namespace vimg::svg {

namespace {

std::string num(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::vector<Subpath> parse_outline(const std::string& d) { return parse_path_data(d, 64).subpaths; }

Element primitive(auto body) {
  Element e;
  e.body = std::move(body);
  return e;
}

struct Converter {
  const ShapeGeometry& g;
  const ShapeSettings& s;
  ShapeOutput out;
  std::size_t points_used = 0;

  double scale() const { return s.ctm.mean_scale(); }

  double line_width_mm() const {
    const double w = s.style.stroke_width * scale();
    return w > 0.0 && std::isfinite(w) ? w : Line{}.width_mm;
  }

  // Flattens within both budgets, counting points as they are produced: the element's (max_points)
  // and the whole import's (points_left, kMaxImportPoints), so that no outline grows past either.
  bool flatten(const Subpath& sp, import::Ring& points) {
    const std::size_t element_room = s.max_points > points_used ? s.max_points - points_used : 0;
    const std::size_t import_room = s.points_left > points_used ? s.points_left - points_used : 0;
    const bool import_bound = import_room < element_room;
    const bool fits = flatten_subpath(sp, s.ctm, s.tolerance_mm, std::min(element_room, import_room), points);
    points_used += points.size();
    out.points = points_used;
    if (fits) return true;
    out.error = import_bound ? "the drawing's curves and outlines flatten to more than " +
                                   std::to_string(kMaxImportPoints) + " points in all (limit " +
                                   std::to_string(kMaxImportPoints) + ")"
                             : "the flattened outline has more than " + std::to_string(s.max_points) +
                                   " points (limit " + std::to_string(s.max_points) + ")";
    return false;
  }

  // LINEs within primitives_left, counted as they are made; false (over_primitives) beyond.
  bool chain(import::Ring points, bool closed) {
    import::remove_repeats(points, closed);
    if (closed && points.size() > 2) points.push_back(points.front());
    const double width = line_width_mm();
    for (std::size_t i = 1; i < points.size(); ++i) {
      if (out.primitives.size() >= s.primitives_left) {
        out.over_primitives = true;
        return false;
      }
      Line l;
      l.x1_mm = points[i - 1].x;
      l.y1_mm = points[i - 1].y;
      l.x2_mm = points[i].x;
      l.y2_mm = points[i].y;
      l.width_mm = width;
      out.primitives.push_back(primitive(l));
    }
    return true;
  }

  bool try_dot() {
    if (g.native != ShapeGeometry::Native::ellipse || g.rx != g.ry || !s.ctm.similarity()) return false;
    const double r = g.rx * scale();
    if (!(r > 0.0) || r > s.dot_max_radius_mm) return false;
    const Vec2 c = s.ctm.apply({g.cx, g.cy});
    out.primitives.push_back(primitive(Dot{c.x, c.y, r, 1.0}));
    return true;
  }

  bool try_native_surface() {
    Surface surface;
    if (g.native == ShapeGeometry::Native::rect && s.ctm.axis_aligned()) {
      const Vec2 a = s.ctm.apply({g.x, g.y}), b = s.ctm.apply({g.x + g.width, g.y + g.height});
      surface.shape = SurfaceShape::rect;
      surface.x_mm = std::min(a.x, b.x);
      surface.y_mm = std::min(a.y, b.y);
      surface.width_mm = std::fabs(b.x - a.x);
      surface.height_mm = std::fabs(b.y - a.y);
    } else if (g.native == ShapeGeometry::Native::ellipse &&
               (s.ctm.axis_aligned() || (s.ctm.similarity() && g.rx == g.ry))) {
      const Vec2 c = s.ctm.apply({g.cx, g.cy});
      surface.shape = SurfaceShape::ellipse;
      surface.cx_mm = c.x;
      surface.cy_mm = c.y;
      surface.rx_mm = s.ctm.axis_aligned() ? g.rx * std::fabs(s.ctm.a) : g.rx * scale();
      surface.ry_mm = s.ctm.axis_aligned() ? g.ry * std::fabs(s.ctm.d) : g.ry * scale();
    } else {
      return false;
    }
    const bool empty = surface.shape == SurfaceShape::rect ? !(surface.width_mm > 0.0 && surface.height_mm > 0.0)
                                                           : !(surface.rx_mm > 0.0 && surface.ry_mm > 0.0);
    if (empty) {
      out.warnings.push_back("has no area after its transforms: no surface");
    } else {
      out.primitives.push_back(primitive(surface));
    }
    return true;
  }

  bool over_outline_tests() {
    if (out.outline_tests <= s.outline_tests_left) return false;
    out.error = "placing the subpaths of this path takes more than " + std::to_string(kMaxImportOutlineTests) +
                " outline tests in the drawing (limit " + std::to_string(kMaxImportOutlineTests) +
                "): paths of fewer subpaths in shorter outlines import faster";
    return true;
  }

  // The nonzero rule as even-odd: a ring is kept only where the fill changes across it, i.e. when
  // the winding number just outside it (the directions of the rings around it) and just inside it
  // differ in being zero. For rings that do not cross, even-odd over the kept rings is the nonzero
  // fill. Beyond kMaxNonzeroRings rings the test would be slow; they stay even-odd, with a warning.
  // A ring is tested only against the rings whose bounding box holds its first point; boxes and
  // edges visited count against outline_tests_left. False when that runs out (out.error says so).
  static constexpr std::size_t kMaxNonzeroRings = 1000;
  bool apply_nonzero(std::vector<import::Ring>& rings) {
    if (s.style.even_odd || rings.size() < 2) return true;
    if (rings.size() > kMaxNonzeroRings) {
      out.warnings.push_back("fill-rule nonzero with more than " + std::to_string(kMaxNonzeroRings) +
                             " subpaths: filled by the even-odd rule");
      return true;
    }
    std::vector<int> direction(rings.size());
    std::vector<Polygon> polygons(rings.size());
    std::vector<Box2> boxes(rings.size());
    for (std::size_t i = 0; i < rings.size(); ++i) {
      direction[i] = import::twice_signed_area(rings[i]) > 0 ? 1 : -1;
      polygons[i].vertices = rings[i];
      boxes[i] = bounding_box(polygons[i]);
    }
    std::vector<import::Ring> kept;
    for (std::size_t i = 0; i < rings.size(); ++i) {
      int outside = 0;
      for (std::size_t j = 0; j < rings.size(); ++j) {
        ++out.outline_tests;
        if (j == i || !boxes[j].contains(rings[i].front())) continue;
        out.outline_tests += rings[j].size();
        if (contains(polygons[j], rings[i].front())) outside += direction[j];
      }
      if (over_outline_tests()) return false;
      if ((outside != 0) != (outside + direction[i] != 0)) kept.push_back(rings[i]);
    }
    rings = std::move(kept);
    return true;
  }

  bool polygon_surface() {
    std::vector<import::Ring> rings;
    for (const Subpath& sp : g.subpaths) {
      if (!sp.closed && !g.lines_only && g.native == ShapeGeometry::Native::none) continue;
      import::Ring ring;
      if (!flatten(sp, ring)) return false;
      import::remove_repeats(ring, true);
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    if (!apply_nonzero(rings)) return false;
    if (rings.empty()) return true;
    std::size_t joined_points = rings.front().size();  // each further ring and its bridge there and back
    for (std::size_t r = 1; r < rings.size(); ++r) joined_points += rings[r].size() + 2;
    if (joined_points > s.max_points) {
      out.error = "a polygon of more than " + std::to_string(s.max_points) + " points (limit " +
                  std::to_string(s.max_points) + ")";
      return false;
    }
    const std::optional<import::Ring> joined = import::bridge_rings(rings, s.outline_tests_left, out.outline_tests);
    if (over_outline_tests() || !joined) return false;  // no ring when over the budget
    Surface surface;
    surface.shape = SurfaceShape::polygon;
    surface.points.reserve(joined->size());
    for (const Vec2& p : *joined) surface.points.push_back({p.x, p.y});
    out.primitives.push_back(primitive(std::move(surface)));
    return true;
  }

  void run() {
    const Style& st = s.style;
    if (g.lines_only) {
      for (const Subpath& sp : g.subpaths) {
        import::Ring points;
        if (!flatten(sp, points) || !chain(std::move(points), sp.closed)) return;
      }
      return;
    }
    if (!st.fill && !st.stroke) {
      out.warnings.push_back("has neither fill nor stroke (it draws nothing): not imported");
      return;
    }
    if (try_dot()) return;
    if (st.fill) {
      if (!try_native_surface() && !polygon_surface()) return;
    }
    for (const Subpath& sp : g.subpaths) {
      // Open subpaths are LINE chains whether filled or stroked; closed ones only when stroked.
      if (!st.stroke && sp.closed) continue;
      import::Ring points;
      if (!flatten(sp, points) || !chain(std::move(points), sp.closed)) return;
    }
  }
};

}  // namespace

namespace {

bool in_range(double v) { return std::isfinite(v) && std::fabs(v) <= kMaxImportCoordinateMm; }

bool in_range(const Element& e) {
  if (const auto* d = std::get_if<Dot>(&e.body)) return in_range(d->x_mm) && in_range(d->y_mm) && in_range(d->radius_mm);
  if (const auto* l = std::get_if<Line>(&e.body)) {
    return in_range(l->x1_mm) && in_range(l->y1_mm) && in_range(l->x2_mm) && in_range(l->y2_mm) && in_range(l->width_mm);
  }
  if (const auto* s = std::get_if<Surface>(&e.body)) {
    for (const double v : {s->x_mm, s->y_mm, s->width_mm, s->height_mm, s->cx_mm, s->cy_mm, s->rx_mm, s->ry_mm}) {
      if (!in_range(v)) return false;
    }
    for (const Point2Mm& p : s->points) {
      if (!in_range(p.x_mm) || !in_range(p.y_mm)) return false;
    }
  }
  return true;
}

}  // namespace

ShapeOutput convert_shape(const ShapeGeometry& geometry, const ShapeSettings& settings) {
  Converter c{geometry, settings, {}, 0};
  c.run();
  for (const Element& e : c.out.primitives) {
    if (!in_range(e)) {
      c.out.primitives.clear();
      c.out.warnings.push_back("has coordinates beyond 1e9 mm (or not finite) after its transforms: not imported");
      break;
    }
  }
  return std::move(c.out);
}

std::vector<Subpath> rect_outline(double x, double y, double w, double h, double rx, double ry) {
  if (rx <= 0.0 || ry <= 0.0) {
    return parse_outline("M" + num(x) + "," + num(y) + " H" + num(x + w) + " V" + num(y + h) + " H" + num(x) + " Z");
  }
  const std::string arc = "A" + num(rx) + "," + num(ry) + " 0 0 1 ";
  return parse_outline("M" + num(x + rx) + "," + num(y) + " H" + num(x + w - rx) + " " + arc + num(x + w) + "," +
                       num(y + ry) + " V" + num(y + h - ry) + " " + arc + num(x + w - rx) + "," + num(y + h) + " H" +
                       num(x + rx) + " " + arc + num(x) + "," + num(y + h - ry) + " V" + num(y + ry) + " " + arc +
                       num(x + rx) + "," + num(y) + " Z");
}

std::vector<Subpath> ellipse_outline(double cx, double cy, double rx, double ry) {
  const std::string arc = "A" + num(rx) + "," + num(ry) + " 0 0 1 ";
  return parse_outline("M" + num(cx + rx) + "," + num(cy) + " " + arc + num(cx) + "," + num(cy + ry) + " " + arc +
                       num(cx - rx) + "," + num(cy) + " " + arc + num(cx) + "," + num(cy - ry) + " " + arc +
                       num(cx + rx) + "," + num(cy) + " Z");
}

}  // namespace vimg::svg
