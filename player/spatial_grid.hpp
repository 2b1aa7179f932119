#pragma once
// A uniform grid over primitive bounding boxes: the collision broad phase. Each primitive is listed
// in every cell its box overlaps; a query visits only the cells its box overlaps, so its cost depends
// on the local density of primitives, not on their total number. Built once per scene, then
// read-only (safe to query from any number of threads).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "player/bounds.hpp"

namespace vimg {

class SpatialGrid {
 public:
  SpatialGrid() = default;
  // About `items_per_cell` boxes per cell on average; at most kMaxCellsPerAxis cells per axis.
  explicit SpatialGrid(std::span<const Bounds2M> boxes, double items_per_cell = 2.0);

  static constexpr int kMaxCellsPerAxis = 2048;

  // Calls f(index) for every box listed in a cell that `query` overlaps. An index may be reported
  // more than once, and boxes that do not intersect `query` may be reported: callers test the box.
  template <class F>
  void for_each_candidate(const Bounds2M& query, F&& f) const {
    if (cells_x_ == 0 || !query.intersects(extent_)) return;
    const int x0 = cell_x(query.min_x_m), x1 = cell_x(query.max_x_m);
    const int y0 = cell_y(query.min_y_m), y1 = cell_y(query.max_y_m);
    for (int cy = y0; cy <= y1; ++cy) {
      for (int cx = x0; cx <= x1; ++cx) {
        const std::size_t cell = static_cast<std::size_t>(cy) * static_cast<std::size_t>(cells_x_) +
                                 static_cast<std::size_t>(cx);
        for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) f(items_[k]);
      }
    }
  }

  int cells_x() const { return cells_x_; }
  int cells_y() const { return cells_y_; }
  const Bounds2M& extent() const { return extent_; }

 private:
  int cell_x(double x_m) const;
  int cell_y(double y_m) const;

  Bounds2M extent_;
  int cells_x_ = 0;
  int cells_y_ = 0;
  double inv_cell_w_ = 0.0;
  double inv_cell_h_ = 0.0;
  std::vector<std::uint32_t> cell_start_;  // CSR offsets, cells_x_ * cells_y_ + 1 entries
  std::vector<std::uint32_t> items_;       // primitive indices, grouped by cell
};

}  // namespace vimg
