#pragma once
// Curves to polylines: a subpath mapped through an affine transform (so that the tolerance is in
// output units, mm) and flattened by adaptive subdivision. A cubic is split in halves until its
// control points lie within `tolerance` of its chord; the curve lies in the hull of its control
// points, so every point of it is then within `tolerance` of the emitted segment. Pure: no I/O.
#include <cstddef>
#include <vector>

#include "primitives/geometry/vec2.hpp"
#include "storage/import/svg_path.hpp"
#include "storage/import/svg_transform.hpp"

namespace vimg::svg {

// Appends the points of the subpath (its start first) to `out`. False when that would exceed
// `max_points` points in `out` (the caller reports the limit; `out` is then incomplete).
bool flatten_subpath(const Subpath& subpath, const Affine& transform, double tolerance, std::size_t max_points,
                     std::vector<Vec2>& out);

}  // namespace vimg::svg
