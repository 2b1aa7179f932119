#pragma once
// A scalar field on a regular grid: trilinear sampling, and gradients by central differences of
// the sampled field one voxel either side (exact for fields that are linear in each cell pair).
#include <utility>
#include <vector>

#include "primitives/volume/grid_geometry.hpp"
#include "primitives/volume/volume_field.hpp"

namespace vimg {

class ScalarGrid final : public ScalarVolume {
 public:
  ScalarGrid() = default;
  // values.size() must equal geometry.size.count(), x fastest; otherwise the grid is empty.
  ScalarGrid(GridGeometry geometry, std::vector<float> values);

  const GridGeometry& geometry() const { return geometry_; }
  const std::vector<float>& values() const { return values_; }
  bool empty() const { return values_.empty(); }
  float at(int i, int j, int k) const { return values_[geometry_.linear_index(i, j, k)]; }

  double value(const Vec3& position_m) const override;
  Vec3 gradient_per_m(const Vec3& position_m) const override;

 private:
  GridGeometry geometry_;
  std::vector<float> values_;
};

}  // namespace vimg
