#pragma once
// Editing an element point by point: the vertices of a polygon SURFACE and the two ends of a
// LINE. Hit tests for a vertex and for a polygon edge (where a double-click inserts a vertex),
// and the edits themselves on a copy of the element (the canvas hands the result to
// DocumentEditor::replace_element, so each is undoable; a drag is one gesture). Pure functions.
#include <cstddef>
#include <optional>
#include <vector>

#include "primitives/image.hpp"

namespace vimg::editor {

// Polygons with more vertices than this show no vertex handles (they would cover the outline
// and cost a handle per vertex every frame); they are still moved and resized as a whole.
inline constexpr std::size_t kMaxHandleVertices = 1000;
// A polygon keeps at least this many vertices (format: points holds at least 3).
inline constexpr std::size_t kMinPolygonVertices = 3;

// The element's editable points, in order: a line's (x1, y1), (x2, y2); a polygon's vertices.
// Empty for every other element, and for polygons over kMaxHandleVertices.
std::vector<Point2Mm> vertex_points(const Element& element);

// The vertex nearest to `p` within `tolerance_mm`, if any (the lowest index on a tie).
std::optional<std::size_t> vertex_at(const Element& element, Point2Mm p, double tolerance_mm);

// A place on a polygon's outline: the vertex would be inserted at `index` (between index-1 and
// index; index == size() means on the closing edge, after the last vertex), at `point`, the foot
// of the perpendicular from the mouse onto that edge.
struct EdgeHit {
  std::size_t index = 0;
  Point2Mm point;
};
// The polygon edge nearest to `p` within `tolerance_mm` (the closing edge included); nothing for
// lines and other elements.
std::optional<EdgeHit> edge_at(const Element& element, Point2Mm p, double tolerance_mm);

// Moves point `index` to `to`. False (element unchanged) when there is no such point.
bool move_vertex(Element& element, std::size_t index, Point2Mm to);
// Inserts a vertex into a polygon at the hit. False when the element is not a polygon or the
// index is past the end.
bool insert_vertex(Element& element, const EdgeHit& hit);
// Deletes a polygon's vertex. False for lines, for other elements, for a bad index, and when
// the polygon would be left with fewer than kMinPolygonVertices.
bool delete_vertex(Element& element, std::size_t index);

}  // namespace vimg::editor
