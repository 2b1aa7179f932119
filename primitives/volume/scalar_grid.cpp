#include "primitives/volume/scalar_grid.hpp"

namespace vimg {

ScalarGrid::ScalarGrid(GridGeometry geometry, std::vector<float> values) : geometry_(geometry) {
  if (values.size() == geometry.size.count() && !values.empty()) values_ = std::move(values);
}

double ScalarGrid::value(const Vec3& position_m) const {
  if (values_.empty()) return 0.0;
  const TrilinearCell c = locate_cell(geometry_.size, geometry_.world_to_voxel(position_m));
  auto v = [&](int i, int j, int k) { return static_cast<double>(at(i, j, k)); };
  const double c00 = v(c.i0, c.j0, c.k0) + c.fx * (v(c.i1, c.j0, c.k0) - v(c.i0, c.j0, c.k0));
  const double c10 = v(c.i0, c.j1, c.k0) + c.fx * (v(c.i1, c.j1, c.k0) - v(c.i0, c.j1, c.k0));
  const double c01 = v(c.i0, c.j0, c.k1) + c.fx * (v(c.i1, c.j0, c.k1) - v(c.i0, c.j0, c.k1));
  const double c11 = v(c.i0, c.j1, c.k1) + c.fx * (v(c.i1, c.j1, c.k1) - v(c.i0, c.j1, c.k1));
  const double c0 = c00 + c.fy * (c10 - c00);
  const double c1 = c01 + c.fy * (c11 - c01);
  return c0 + c.fz * (c1 - c0);
}

Vec3 ScalarGrid::gradient_per_m(const Vec3& position_m) const {
  if (values_.empty()) return {};
  const Vec3 h = geometry_.spacing_m;
  const Vec3 dx{h.x, 0.0, 0.0};
  const Vec3 dy{0.0, h.y, 0.0};
  const Vec3 dz{0.0, 0.0, h.z};
  return {(value(position_m + dx) - value(position_m - dx)) / (2.0 * h.x),
          (value(position_m + dy) - value(position_m - dy)) / (2.0 * h.y),
          (value(position_m + dz) - value(position_m - dz)) / (2.0 * h.z)};
}

}  // namespace vimg
