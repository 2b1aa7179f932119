#pragma once
// Outlines of a binary mask (marching squares) and their simplification (Douglas-Peucker).
// Samples sit at pixel centres and the mask is taken as 0 outside the picture, so every outline is
// a closed ring through the midpoints of pixel edges (coordinates in pixels, x right, y down, the
// picture's top-left corner at 0,0). Where two set pixels touch only at a corner (a saddle), they
// are kept apart, for every mask alike. Rings keep the set pixels on their left as seen on screen:
// outer outlines have twice_signed_area() < 0 in these coordinates, holes > 0. Pure: no I/O.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "storage/import/rings.hpp"

namespace vimg::import {

// `mask` has width * height entries, rows top to bottom; non-zero is set.
std::vector<Ring> trace_contours(const std::vector<std::uint8_t>& mask, int width, int height);

// The closed ring simplified so that every dropped point lies within `tolerance` of the kept
// outline (Douglas-Peucker, anchored at the first point and the point farthest from it).
Ring simplify_ring(const Ring& ring, double tolerance);

}  // namespace vimg::import
