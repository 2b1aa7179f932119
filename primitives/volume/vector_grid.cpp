#include "primitives/volume/vector_grid.hpp"

#include <utility>

namespace vimg {

VectorGrid::VectorGrid(GridGeometry geometry, std::vector<float> components) : geometry_(geometry) {
  if (components.size() == 3 * geometry.size.count() && !components.empty()) {
    components_ = std::move(components);
  }
}

Vec3 VectorGrid::vector(const Vec3& position_m) const {
  if (components_.empty()) return {};
  const TrilinearCell c = locate_cell(geometry_.size, geometry_.world_to_voxel(position_m));
  const Vec3 c00 = at(c.i0, c.j0, c.k0) + c.fx * (at(c.i1, c.j0, c.k0) - at(c.i0, c.j0, c.k0));
  const Vec3 c10 = at(c.i0, c.j1, c.k0) + c.fx * (at(c.i1, c.j1, c.k0) - at(c.i0, c.j1, c.k0));
  const Vec3 c01 = at(c.i0, c.j0, c.k1) + c.fx * (at(c.i1, c.j0, c.k1) - at(c.i0, c.j0, c.k1));
  const Vec3 c11 = at(c.i0, c.j1, c.k1) + c.fx * (at(c.i1, c.j1, c.k1) - at(c.i0, c.j1, c.k1));
  const Vec3 c0 = c00 + c.fy * (c10 - c00);
  const Vec3 c1 = c01 + c.fy * (c11 - c01);
  return c0 + c.fz * (c1 - c0);
}

}  // namespace vimg
