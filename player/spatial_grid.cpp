#include "player/spatial_grid.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

SpatialGrid::SpatialGrid(std::span<const Bounds2M> boxes, double items_per_cell) {
  if (boxes.empty()) return;
  extent_ = boxes[0];
  for (const auto& b : boxes) extent_ = extent_.united(b);
  const double w = std::max(extent_.max_x_m - extent_.min_x_m, 1e-9);
  const double h = std::max(extent_.max_y_m - extent_.min_y_m, 1e-9);
  // Square-ish cells, about items_per_cell boxes per cell.
  const double cells = std::max(1.0, static_cast<double>(boxes.size()) / std::max(items_per_cell, 0.1));
  const double cell_size = std::sqrt(w * h / cells);
  // Clamped before the conversion: a box a billion times longer than wide (or a width that
  // overflows to infinity) asks for more cells than an int holds.
  const auto axis_cells = [](double extent, double cell) {
    const double n = std::ceil(extent / cell);
    return static_cast<int>(std::clamp(std::isnan(n) ? double{kMaxCellsPerAxis} : n, 1.0, double{kMaxCellsPerAxis}));
  };
  cells_x_ = axis_cells(w, cell_size);
  cells_y_ = axis_cells(h, cell_size);
  inv_cell_w_ = cells_x_ / w;
  inv_cell_h_ = cells_y_ / h;

  const std::size_t n_cells = static_cast<std::size_t>(cells_x_) * static_cast<std::size_t>(cells_y_);
  cell_start_.assign(n_cells + 1, 0);
  auto for_cells = [&](const Bounds2M& b, auto&& f) {
    const int x0 = cell_x(b.min_x_m), x1 = cell_x(b.max_x_m);
    const int y0 = cell_y(b.min_y_m), y1 = cell_y(b.max_y_m);
    for (int cy = y0; cy <= y1; ++cy)
      for (int cx = x0; cx <= x1; ++cx)
        f(static_cast<std::size_t>(cy) * static_cast<std::size_t>(cells_x_) + static_cast<std::size_t>(cx));
  };
  for (const auto& b : boxes) for_cells(b, [&](std::size_t c) { ++cell_start_[c + 1]; });
  for (std::size_t c = 0; c < n_cells; ++c) cell_start_[c + 1] += cell_start_[c];
  items_.resize(cell_start_[n_cells]);
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for_cells(boxes[i], [&](std::size_t c) { items_[fill[c]++] = static_cast<std::uint32_t>(i); });
  }
}

// NaN (an infinite extent times a zero scale) counts as the first cell.
int SpatialGrid::cell_x(double x_m) const {
  const double c = std::floor((x_m - extent_.min_x_m) * inv_cell_w_);
  return std::isnan(c) ? 0 : static_cast<int>(std::clamp(c, 0.0, static_cast<double>(cells_x_ - 1)));
}

int SpatialGrid::cell_y(double y_m) const {
  const double c = std::floor((y_m - extent_.min_y_m) * inv_cell_h_);
  return std::isnan(c) ? 0 : static_cast<int>(std::clamp(c, 0.0, static_cast<double>(cells_y_ - 1)));
}

}  // namespace vimg
