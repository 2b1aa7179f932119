#pragma once
// Plane geometry of document elements, in millimetres: bounds, hit tests, moves and resizes.
// Pure functions over the document model; the canvas and the editing commands both use them.
#include <optional>

#include "primitives/image.hpp"

namespace vimg::editor {

struct RectMm {
  double x0_mm = 0.0;
  double y0_mm = 0.0;
  double x1_mm = 0.0;
  double y1_mm = 0.0;
  double width_mm() const { return x1_mm - x0_mm; }
  double height_mm() const { return y1_mm - y0_mm; }
  bool contains(Point2Mm p) const { return p.x_mm >= x0_mm && p.x_mm <= x1_mm && p.y_mm >= y0_mm && p.y_mm <= y1_mm; }
  bool intersects(const RectMm& o) const {
    return x0_mm <= o.x1_mm && o.x0_mm <= x1_mm && y0_mm <= o.y1_mm && o.y0_mm <= y1_mm;
  }
  friend bool operator==(const RectMm&, const RectMm&) = default;
};

// The rectangle spanned by two corners given in any order.
RectMm rect_from_corners(Point2Mm a, Point2Mm b);
RectMm united(const RectMm& a, const RectMm& b);

// The axis-aligned bounds of what can be felt (a line includes its band). Empty groups and
// unknown elements have no bounds.
std::optional<RectMm> element_bounds(const Element& element);

// Whether the point lies on the element, with `tolerance_mm` of slack for thin shapes.
bool element_contains(const Element& element, Point2Mm point, double tolerance_mm);

// Distance from p to the segment a-b.
double distance_to_segment_mm(Point2Mm p, Point2Mm a, Point2Mm b);

void translate_element(Element& element, double dx_mm, double dy_mm);

// Maps the element's geometry from `from` onto `to` (a resize by its handles). Sizes that cannot
// stretch unevenly (a dot's radius, a line's width) scale by the mean factor. Sizes stay > 0.
void map_element(Element& element, const RectMm& from, const RectMm& to);

// Rounds to the nearest multiple of step_mm (no snapping when step_mm <= 0).
double snap_mm(double value_mm, double step_mm);

}  // namespace vimg::editor
