// The uniform grid with boxes no drawing would make but a hostile file can (found by the .vsc
// fuzzer): a box 1e131 m long on a grid whose floor height is 1e-9 m, and boxes whose extent
// overflows to infinity. The cell counts stay in [1, kMaxCellsPerAxis] without converting an
// out-of-range double to int (clang's UBSan in the fuzz build caught that conversion; g++'s
// -fsanitize=undefined does not check it), and every box is still found by a query that contains
// it (with an infinite extent the old grid indexed outside its cells and crashed).
#include <gtest/gtest.h>

#include <vector>

#include "player/spatial_grid.hpp"

namespace vimg {
namespace {

void expect_every_box_found(const std::vector<Bounds2M>& boxes) {
  const SpatialGrid grid(boxes);
  EXPECT_GE(grid.cells_x(), 1);
  EXPECT_LE(grid.cells_x(), SpatialGrid::kMaxCellsPerAxis);
  EXPECT_GE(grid.cells_y(), 1);
  EXPECT_LE(grid.cells_y(), SpatialGrid::kMaxCellsPerAxis);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    bool found = false;
    grid.for_each_candidate(boxes[i], [&](std::size_t c) { found = found || c == i; });
    EXPECT_TRUE(found) << "box " << i;
  }
}

TEST(SpatialGridExtremes, ABoxFarLongerThanTheFloorHeightGivesAtMostTheMaximumCells) {
  expect_every_box_found({{0.0, 0.0, 4.2e131, 0.0}, {0.0, 0.0, 0.0, 0.0}});
  expect_every_box_found({{0.0, 0.0, 0.0, 4.2e131}, {1e-3, 0.0, 1e-3, 0.0}});
}

TEST(SpatialGridExtremes, AnExtentThatOverflowsToInfinityStillFindsEveryBox) {
  expect_every_box_found({{-1.7e308, -1.7e308, -1.6e308, -1.6e308}, {1.6e308, 1.6e308, 1.7e308, 1.7e308},
                          {0.0, 0.0, 1.0, 1.0}});
}

}  // namespace
}  // namespace vimg
