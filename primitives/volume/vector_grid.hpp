#pragma once
// A 3-vector field on a regular grid, sampled trilinearly per component.
#include <vector>

#include "primitives/volume/grid_geometry.hpp"
#include "primitives/volume/volume_field.hpp"

namespace vimg {

class VectorGrid final : public VectorVolume {
 public:
  VectorGrid() = default;
  // components holds x, y, z interleaved per voxel (x fastest over voxels), so its size must be
  // 3 * geometry.size.count(); otherwise the grid is empty.
  VectorGrid(GridGeometry geometry, std::vector<float> components);

  const GridGeometry& geometry() const { return geometry_; }
  const std::vector<float>& components() const { return components_; }
  bool empty() const { return components_.empty(); }
  Vec3 at(int i, int j, int k) const {
    const std::size_t n = 3 * geometry_.linear_index(i, j, k);
    return {components_[n], components_[n + 1], components_[n + 2]};
  }

  Vec3 vector(const Vec3& position_m) const override;

 private:
  GridGeometry geometry_;
  std::vector<float> components_;
};

}  // namespace vimg
