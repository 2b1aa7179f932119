#pragma once
// Closed rings (outlines) to the one polygon a SURFACE holds. A SURFACE polygon is filled by the
// even-odd rule (docs/format-png.md), so several rings, holes included, become one point list: each
// further ring is joined to the first by a bridge, an edge walked there and back (r_i -> h_0 ...
// h_0 -> r_i). The two bridge edges coincide, so every ray crosses both or neither and the
// even-odd fill is exactly that of the separate rings. Pure: no I/O.
#include <cstddef>
#include <optional>
#include <vector>

#include "primitives/geometry/vec2.hpp"

namespace vimg::import {

using Ring = std::vector<Vec2>;

// Twice the signed area (shoelace); > 0 counter-clockwise in a y-up frame.
double twice_signed_area(const Ring& ring);

// Drops repeated consecutive points and, for a closed ring, a last point equal to the first.
void remove_repeats(Ring& ring, bool closed);

// One point list for the even-odd union of `rings` (each at least 3 points): the first ring,
// with every other ring bridged from the vertex of the first ring nearest to its own first point.
Ring bridge_rings(const std::vector<Ring>& rings);
// The same within a work budget: `work` grows by the vertices looked at (the first ring's once, and
// those near each further ring's first point); nothing when it would pass `max_work`.
std::optional<Ring> bridge_rings(const std::vector<Ring>& rings, std::size_t max_work, std::size_t& work);

}  // namespace vimg::import
