#pragma once
// What the canvas's drawing tools make, and how a selection box follows its handles: pure
// functions of millimetre positions, so the canvas only turns the mouse into them.
#include <array>
#include <optional>
#include <vector>

#include "editor/core/geometry.hpp"

namespace vimg::editor {

enum class Tool { select, dot, line, rect, ellipse, polygon };

// The element a drag from `a` to `b` places with `tool` (dot, line, rect, ellipse). A drag
// shorter than 3 px on screen is a click and places the default size: a 2 mm dot, a 20 mm line to
// the right, a 20 x 20 mm rectangle from `a`, an ellipse of radius 10 mm around `a`. Nothing for
// the select and polygon tools.
std::optional<Element> place_element(Tool tool, Point2Mm a, Point2Mm b, double px_per_mm);

// A polygon SURFACE through the points; nothing with fewer than 3.
std::optional<Element> polygon_element(const std::vector<Point2Mm>& points);

// The eight handles of a selection box, clockwise from the top-left corner: which of the box's
// x (0 left, 1 middle, 2 right) and y (0 top, 1 middle, 2 bottom) each one sits on.
inline constexpr std::array<int, 8> kHandleColumn = {0, 1, 2, 2, 2, 1, 0, 0};
inline constexpr std::array<int, 8> kHandleRow = {0, 0, 0, 1, 2, 2, 2, 1};
inline constexpr double kMinResizedSideMm = 0.1;

// The handle's position on the box.
Point2Mm handle_position(const RectMm& box, int handle);

// The box `from` with handle `handle` dragged by (dx, dy) mm. With snap_step_mm > 0 the drag is
// rounded to whole steps first, as a move is (geometry.hpp snap_mm): the edges the handle holds
// move by whole grid steps. A side never becomes shorter than kMinResizedSideMm (the dragged
// edge stops there: a box is not flipped by dragging a handle past the opposite edge).
RectMm resized_box(const RectMm& from, int handle, double dx_mm, double dy_mm, double snap_step_mm);

}  // namespace vimg::editor
