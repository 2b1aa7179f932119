#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "primitives/volume/scalar_grid.hpp"
#include "primitives/volume/vector_grid.hpp"

namespace vimg {
namespace {

GridGeometry small_geometry() {
  GridGeometry g;
  g.size = {7, 6, 5};
  g.origin_m = {-0.01, 0.02, -0.005};
  g.spacing_m = {0.002, 0.001, 0.003};
  return g;
}

template <class F>
ScalarGrid sample(const GridGeometry& g, F f) {
  std::vector<float> values(g.size.count());
  for (int k = 0; k < g.size.nz; ++k)
    for (int j = 0; j < g.size.ny; ++j)
      for (int i = 0; i < g.size.nx; ++i)
        values[g.linear_index(i, j, k)] = static_cast<float>(f(g.voxel_to_world(
            {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)})));
  return ScalarGrid(g, std::move(values));
}

TEST(GridGeometry, WorldAndVoxelAreInverse) {
  const GridGeometry g = small_geometry();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (int n = 0; n < 1000; ++n) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 back = g.voxel_to_world(g.world_to_voxel(p));
    EXPECT_NEAR(back.x, p.x, 1e-15);
    EXPECT_NEAR(back.y, p.y, 1e-15);
    EXPECT_NEAR(back.z, p.z, 1e-15);
  }
  EXPECT_EQ(g.world_to_voxel(g.origin_m), Vec3{});
}

TEST(ScalarGrid, TrilinearReproducesTrilinearFunctionsInside) {
  // Trilinear interpolation is exact for a + bx + cy + dz + exy + fyz + gxz + hxyz.
  const GridGeometry g = small_geometry();
  auto f = [](const Vec3& p) { return 1.0 + 30 * p.x - 20 * p.y + 10 * p.z + 400 * p.x * p.y + 2e4 * p.x * p.y * p.z; };
  const ScalarGrid grid = sample(g, f);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  const Vec3 lo = g.origin_m, hi = g.far_corner_m();
  for (int n = 0; n < 1000; ++n) {
    const Vec3 p{lo.x + t(rng) * (hi.x - lo.x), lo.y + t(rng) * (hi.y - lo.y), lo.z + t(rng) * (hi.z - lo.z)};
    EXPECT_NEAR(grid.value(p), f(p), 1e-5) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(ScalarGrid, ValuesAtVoxelsAreExactAndOutsideIsClampedToTheFaces) {
  const GridGeometry g = small_geometry();
  const ScalarGrid grid = sample(g, [](const Vec3& p) { return 100.0 * p.x; });
  EXPECT_FLOAT_EQ(static_cast<float>(grid.value(g.voxel_to_world({2, 3, 4}))), grid.at(2, 3, 4));
  EXPECT_NEAR(grid.value(g.origin_m - Vec3{1.0, 0, 0}), grid.at(0, 0, 0), 1e-12);
  EXPECT_NEAR(grid.value(g.far_corner_m() + Vec3{1.0, 1.0, 1.0}), grid.at(6, 5, 4), 1e-12);
}

TEST(ScalarGrid, CentralDifferenceGradientIsExactForLinearFields) {
  const GridGeometry g = small_geometry();
  const Vec3 a{3.0, -7.0, 11.0};
  const ScalarGrid grid = sample(g, [&](const Vec3& p) { return dot(a, p) + 0.5; });
  // One voxel away from every face, the differences see only the field.
  const Vec3 p = g.voxel_to_world({2.3, 2.6, 1.5});
  const Vec3 gradient = grid.gradient_per_m(p);
  EXPECT_NEAR(gradient.x, a.x, 1e-4);
  EXPECT_NEAR(gradient.y, a.y, 1e-4);
  EXPECT_NEAR(gradient.z, a.z, 1e-4);
}

TEST(ScalarGrid, CentralDifferenceGradientApproximatesSmoothFields) {
  GridGeometry g;
  g.size = {41, 41, 41};
  g.origin_m = {-0.02, -0.02, -0.02};
  g.spacing_m = {0.001, 0.001, 0.001};
  const ScalarGrid grid = sample(g, [](const Vec3& p) { return std::sin(100.0 * p.x) * std::cos(80.0 * p.z); });
  const Vec3 p{0.0031, 0.004, -0.0052};
  const Vec3 gradient = grid.gradient_per_m(p);
  EXPECT_NEAR(gradient.x, 100.0 * std::cos(100.0 * p.x) * std::cos(80.0 * p.z), 3.0);
  EXPECT_NEAR(gradient.y, 0.0, 1e-6);
  EXPECT_NEAR(gradient.z, -80.0 * std::sin(100.0 * p.x) * std::sin(80.0 * p.z), 3.0);
}

TEST(ScalarGrid, WrongValueCountGivesAnEmptyGridThatSamplesZero) {
  const ScalarGrid grid(small_geometry(), std::vector<float>(3, 1.0f));
  EXPECT_TRUE(grid.empty());
  EXPECT_EQ(grid.value({}), 0.0);
  EXPECT_EQ(grid.gradient_per_m({}), Vec3{});
}

TEST(VectorGrid, TrilinearPerComponent) {
  const GridGeometry g = small_geometry();
  std::vector<float> c(3 * g.size.count());
  auto f = [](const Vec3& p) { return Vec3{10 * p.x + 1, -5 * p.y, 7 * p.z + 20 * p.x}; };
  for (int k = 0; k < g.size.nz; ++k)
    for (int j = 0; j < g.size.ny; ++j)
      for (int i = 0; i < g.size.nx; ++i) {
        const Vec3 v = f(g.voxel_to_world({double(i), double(j), double(k)}));
        const std::size_t n = 3 * g.linear_index(i, j, k);
        c[n] = float(v.x), c[n + 1] = float(v.y), c[n + 2] = float(v.z);
      }
  const VectorGrid grid(g, std::move(c));
  const Vec3 p = g.voxel_to_world({1.25, 4.5, 2.75});
  const Vec3 v = grid.vector(p), e = f(p);
  EXPECT_NEAR(v.x, e.x, 1e-5);
  EXPECT_NEAR(v.y, e.y, 1e-5);
  EXPECT_NEAR(v.z, e.z, 1e-5);
}

}  // namespace
}  // namespace vimg
