#pragma once
// The placement of a regular, axis-aligned grid in the world: voxel (i, j, k) sits at
// origin_m + (i * spacing_m.x, j * spacing_m.y, k * spacing_m.z). Indices are continuous, so a
// world point maps to a fractional voxel coordinate and back.
#include <cstddef>

#include "primitives/vec3.hpp"

namespace vimg {

struct GridSize {
  int nx = 0;
  int ny = 0;
  int nz = 0;
  std::size_t count() const {
    return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
  }
  friend bool operator==(const GridSize&, const GridSize&) = default;
};

struct GridGeometry {
  GridSize size;
  Vec3 origin_m;                     // world position of voxel (0, 0, 0)
  Vec3 spacing_m{1e-3, 1e-3, 1e-3};  // distance between neighbouring voxels, > 0 on each axis

  Vec3 world_to_voxel(const Vec3& world_m) const {
    return {(world_m.x - origin_m.x) / spacing_m.x, (world_m.y - origin_m.y) / spacing_m.y,
            (world_m.z - origin_m.z) / spacing_m.z};
  }
  Vec3 voxel_to_world(const Vec3& voxel) const {
    return {origin_m.x + voxel.x * spacing_m.x, origin_m.y + voxel.y * spacing_m.y,
            origin_m.z + voxel.z * spacing_m.z};
  }
  // World position of the last voxel: the far corner of the sampled box.
  Vec3 far_corner_m() const {
    return voxel_to_world({static_cast<double>(size.nx - 1), static_cast<double>(size.ny - 1),
                           static_cast<double>(size.nz - 1)});
  }
  std::size_t linear_index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(size.ny) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(size.nx) +
           static_cast<std::size_t>(i);
  }
  friend bool operator==(const GridGeometry&, const GridGeometry&) = default;
};

// Where a fractional voxel coordinate falls: the lower corner of its cell and the weights inside
// it. Points outside the grid are clamped to its boundary (the data is extended at the faces).
struct TrilinearCell {
  int i0 = 0, j0 = 0, k0 = 0;
  int i1 = 0, j1 = 0, k1 = 0;
  double fx = 0.0, fy = 0.0, fz = 0.0;
};

TrilinearCell locate_cell(const GridSize& size, const Vec3& voxel);

}  // namespace vimg
