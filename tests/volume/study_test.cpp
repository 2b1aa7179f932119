#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "player/haptic/probe_render.hpp"
#include "primitives/volume/study_set.hpp"
#include "storage/volume/study_writer.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

TEST(StudySet, LayoutIsSeededAndInRange) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    const StudyLayout a = study_layout(seed);
    EXPECT_GE(a.bend_x_mm, -40.0);
    EXPECT_LE(a.bend_x_mm, 40.0);
    EXPECT_GE(a.plane_z_mm, -30.0);
    EXPECT_LE(a.plane_z_mm, 30.0);
    EXPECT_EQ(a.bend_x_mm, study_layout(seed).bend_x_mm);
  }
  EXPECT_NE(study_layout(1).bend_x_mm, study_layout(2).bend_x_mm);
}

TEST(StudySet, FlowIsStraightThenBendsOver20mmIntoTheDiagonal) {
  const StudySet set = make_study_set(5);
  const double b = set.layout.bend_x_mm;
  for (double y : {-30.0, 0.0, 41.0}) {
    const Vec3 before = set.flow.vector(Vec3{b - 12.5, y, 3.0} * 1e-3);
    EXPECT_NEAR(before.x, 1.0, 1e-6);
    EXPECT_NEAR(before.z, 0.0, 1e-6);
    const Vec3 after = set.flow.vector(Vec3{b + 12.5, y, -7.0} * 1e-3);
    EXPECT_NEAR(after.x, std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(after.z, std::sqrt(0.5), 1e-6);
  }
  // Inside the bend the angle grows with x (the grid cell that holds the bend's ends blends in).
  double last = -1.0;
  for (double x = b - 9.0; x <= b + 9.0; x += 2.0) {
    const Vec3 v = set.flow.vector(Vec3{x, 0.0, 0.0} * 1e-3);
    const double angle = std::atan2(v.z, v.x);
    EXPECT_GT(angle, last);
    last = angle;
  }
}

TEST(StudySet, FeatureIsTheSignedDistanceToThePlane) {
  const StudySet set = make_study_set(6);
  for (double z = -55.0; z <= 55.0; z += 3.7) {
    EXPECT_NEAR(set.feature.value(Vec3{12.3, -4.0, z} * 1e-3), z - set.layout.plane_z_mm, 1e-4);
  }
}

// End to end: write the study set, load its scene, render a probe path.
class StudyEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("vimg_study_e2e_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    set_ = make_study_set(20240611);
    ASSERT_FALSE(write_study_set(set_, dir_).has_value());
    VolumeSceneLoadResult r = load_volume_scene_file(dir_ / kStudySceneFileName);
    ASSERT_TRUE(r.ok());
    loaded_ = std::move(*r.loaded);
    scene_ = build_haptic_scene(loaded_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::vector<ProbeForceRow> render(const std::vector<ProbePathPoint>& path) {
    return render_probe_path(*scene_, path, loaded_.scene.device.rate_hz, loaded_.scene.device.max_force_N);
  }

  std::filesystem::path dir_;
  StudySet set_;
  LoadedVolumeScene loaded_;
  std::unique_ptr<HapticScene> scene_;
};

TEST_F(StudyEndToEnd, TheCueRingsFromThePlane) {
  // Along z at 50 mm/s through the plane, then holding still 1 mm past it: the roughness stops
  // (no speed) and only the cue rings, with its phase counted from the plane crossing.
  const double z0 = set_.layout.plane_z_mm, v = 50.0;
  const double t_stop = 31.0 / v;
  const std::vector<ProbePathPoint> path = {{0.0, Vec3{-60.0, 0.0, z0 - 30.0} * 1e-3},
                                            {t_stop, Vec3{-60.0, 0.0, z0 + 1.0} * 1e-3},
                                            {t_stop + 0.6, Vec3{-60.0, 0.0, z0 + 1.0} * 1e-3}};
  const auto rows = render(path);
  const double t_cross = 30.0 / v;
  const double beta = 1.0 / 0.1, omega0 = 2.0 * std::numbers::pi * 130.0;
  const double omega_d = std::sqrt(omega0 * omega0 - beta * beta);
  int checked = 0;
  double peak = 0.0;
  for (const auto& r : rows) {
    if (r.time_s <= t_stop + 0.002) continue;
    const double tp = r.time_s - t_cross;
    const double expected = 0.3 * std::exp(-beta * tp) * std::sin(omega_d * tp);
    EXPECT_NEAR(r.vibrotactile_N.y, expected, 0.01) << "t=" << r.time_s;
    peak = std::max(peak, std::abs(r.vibrotactile_N.y));
    ++checked;
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(peak, 0.1);
  // Before the plane only the roughness plays: the vibration stays within its amplitude.
  for (const auto& r : rows) {
    if (r.time_s < t_cross - 0.01) {
      EXPECT_LE(std::abs(r.vibrotactile_N.y), 0.6 + 1e-9);
    }
  }
}

// Zero crossings of the vibration along a path segment between two distances from the plane.
int crossings(const std::vector<ProbeForceRow>& rows, double z0, double from_mm, double to_mm) {
  int n = 0;
  double last = 0.0;
  for (const auto& r : rows) {
    const double d = r.position_m.z * 1e3 - z0;
    if (d < from_mm || d > to_mm) continue;
    const double y = r.vibrotactile_N.y;
    if (last != 0.0 && y != 0.0 && (y > 0.0) != (last > 0.0)) ++n;
    if (y != 0.0) last = y;
  }
  return n;
}

// Expected zero crossings: the phase alpha = integral omega |dx| over the segment, divided by pi.
double expected_crossings(double from_mm, double to_mm) {
  double alpha = 0.0;
  const double step = 0.001;
  for (double d = from_mm + step / 2; d < to_mm; d += step) {
    const double w = std::min(std::abs(d), 20.0) / 20.0;
    const double period = 2.5 + w * (0.4 - 2.5);
    alpha += 2.0 * std::numbers::pi / period * step;
  }
  return alpha / std::numbers::pi;
}

TEST_F(StudyEndToEnd, RoughnessFrequencyFallsAcrossTheBand) {
  const double z0 = set_.layout.plane_z_mm, v = 40.0;
  const std::vector<ProbePathPoint> path = {{0.0, Vec3{30.0, 5.0, z0 - 45.0} * 1e-3},
                                            {45.0 / v, Vec3{30.0, 5.0, z0} * 1e-3}};
  const auto rows = render(path);
  // Far from the plane: period 0.4 mm -> v / 0.4 mm = 100 Hz; the crossings count the phase.
  const int far = crossings(rows, z0, -40.0, -20.0);
  EXPECT_NEAR(far, expected_crossings(-40.0, -20.0), 2.0);
  EXPECT_NEAR(far / (20.0 / v) / 2.0, v / 0.4, 2.5);  // Hz = v * omega / 2 pi
  const int band = crossings(rows, z0, -20.0, -2.0);
  EXPECT_NEAR(band, expected_crossings(-20.0, -2.0), 2.0);
  const int near_plane = crossings(rows, z0, -6.0, -1.0);
  EXPECT_NEAR(near_plane, expected_crossings(-6.0, -1.0), 1.5);
  // Per mm travelled, the texture near the plane is several times coarser than far from it.
  EXPECT_GT(far / 20.0, 4.0 * near_plane / 5.0);
  // Amplitude: 0.6 N far from the plane at full speed, falling towards 0.3 N at it.
  double far_peak = 0.0, near_peak = 0.0;
  for (const auto& r : rows) {
    const double d = r.position_m.z * 1e3 - z0;
    if (d < -25.0 && r.time_s > 0.1) far_peak = std::max(far_peak, std::abs(r.vibrotactile_N.y));
    if (d > -2.0 && d < -0.5) near_peak = std::max(near_peak, std::abs(r.vibrotactile_N.y));
  }
  // Sampled at 1 kHz, a 100 Hz sine shows at least cos(pi * 100 / 1000) of its peak.
  EXPECT_LE(far_peak, 0.6 + 1e-9);
  EXPECT_GE(far_peak, 0.6 * std::cos(std::numbers::pi * 0.1) - 1e-6);
  EXPECT_LT(near_peak, 0.34);
  EXPECT_GT(near_peak, 0.25);
}

TEST_F(StudyEndToEnd, GuidanceResistsCrossingTheFlowButNotFollowingIt) {
  const double x0 = set_.layout.bend_x_mm - 40.0;  // straight flow along x here
  // Along the flow: the kinaesthetic force stays near zero (only damping transients).
  auto rows = render({{0.0, Vec3{x0, 0.0, 0.0} * 1e-3}, {0.5, Vec3{x0 + 25.0, 0.0, 0.0} * 1e-3}});
  for (std::size_t i = 2; i < rows.size(); ++i) EXPECT_LT(norm(rows[i].kinaesthetic_N), 0.05);
  // Across it (along y): resisted up to the across force, 1.5 N.
  rows = render({{0.0, Vec3{x0, 0.0, 0.0} * 1e-3}, {0.5, Vec3{x0, 25.0, 0.0} * 1e-3}});
  double peak = 0.0;
  for (const auto& r : rows) peak = std::max(peak, std::abs(r.kinaesthetic_N.y));
  EXPECT_GT(peak, 1.4);
  EXPECT_LT(peak, 1.5 + 0.5 * 0.05 + 1e-6);  // across force plus k_d times the speed
  for (const auto& r : rows) EXPECT_LE(norm(r.total_N), 3.3 + 1e-12);
}

}  // namespace
}  // namespace vimg
