#include "primitives/volume/grid_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {
namespace {

// One axis: clamps u into [0, n-1] and splits it into a cell index and a fraction.
void locate_axis(int n, double u, int& lower, int& upper, double& fraction) {
  if (n <= 1 || !(u > 0.0)) {  // also catches NaN
    lower = upper = 0;
    fraction = 0.0;
    return;
  }
  const double last = static_cast<double>(n - 1);
  if (u >= last) {
    lower = upper = n - 1;
    fraction = 0.0;
    return;
  }
  const double floor_u = std::floor(u);
  lower = static_cast<int>(floor_u);
  upper = std::min(lower + 1, n - 1);
  fraction = u - floor_u;
}

}  // namespace

TrilinearCell locate_cell(const GridSize& size, const Vec3& voxel) {
  TrilinearCell c;
  locate_axis(size.nx, voxel.x, c.i0, c.i1, c.fx);
  locate_axis(size.ny, voxel.y, c.j0, c.j1, c.fy);
  locate_axis(size.nz, voxel.z, c.k0, c.k1, c.fz);
  return c;
}

}  // namespace vimg
