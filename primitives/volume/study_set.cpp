#include "primitives/volume/study_set.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace vimg {

StudyLayout study_layout(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  // Uniform from raw bits, so the layout is the same with every standard library.
  auto uniform = [&](double lo, double hi) {
    const double u = static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
    return lo + u * (hi - lo);
  };
  StudyLayout layout;
  layout.bend_x_mm = uniform(-40.0, 40.0);
  layout.plane_z_mm = uniform(-30.0, 30.0);
  return layout;
}

Vec3 study_flow_direction(double x_mm, double bend_x_mm) {
  const double t = std::clamp((x_mm - (bend_x_mm - kStudyBendWidthMm / 2)) / kStudyBendWidthMm, 0.0, 1.0);
  const double angle = t * std::numbers::pi / 4.0;
  return {std::cos(angle), 0.0, std::sin(angle)};
}

StudySet make_study_set(std::uint64_t seed) {
  StudySet set;
  set.layout = study_layout(seed);
  GridGeometry g;
  g.size = {81, 61, 61};
  g.origin_m = {-0.080, -0.060, -0.060};
  g.spacing_m = {0.002, 0.002, 0.002};
  std::vector<float> feature(g.size.count());
  std::vector<float> flow(3 * g.size.count());
  for (int k = 0; k < g.size.nz; ++k) {
    for (int j = 0; j < g.size.ny; ++j) {
      for (int i = 0; i < g.size.nx; ++i) {
        const Vec3 p_mm = g.voxel_to_world({double(i), double(j), double(k)}) * 1e3;
        const std::size_t n = g.linear_index(i, j, k);
        feature[n] = static_cast<float>(p_mm.z - set.layout.plane_z_mm);
        const Vec3 v = study_flow_direction(p_mm.x, set.layout.bend_x_mm);
        flow[3 * n] = static_cast<float>(v.x);
        flow[3 * n + 1] = static_cast<float>(v.y);
        flow[3 * n + 2] = static_cast<float>(v.z);
      }
    }
  }
  set.feature = ScalarGrid(g, std::move(feature));
  set.flow = VectorGrid(g, std::move(flow));

  VolumeScene& s = set.scene;
  s.data = {{"feature", VolumeDataRef::Kind::scalar, "feature.nrrd", 0}, {"flow", VolumeDataRef::Kind::vector, "flow.nrrd", 0}};
  s.device = DeviceProfile{"desktop", 3.3, 400.0, {160.0, 120.0, 120.0}, 1000.0, 0.2, 500.0};
  KinaestheticSpec k;
  k.mode = KinaestheticMode::vector_guidance;
  k.data = "flow";
  k.stiffness_N_per_m = 300.0;
  k.damping_N_s_per_m = 0.5;
  k.across_force_N = 1.5;
  s.kinaesthetic = k;
  RoughnessSpec r;
  r.data = "feature";
  r.direction = {0.0, 1.0, 0.0};
  r.omega_given_as_period = true;
  const double w = kStudyBandHalfWidthMm;
  r.omega_points = {{-w, 0.4}, {0.0, 2.5}, {w, 0.4}};
  r.amplitude_points = {{-w, 0.6}, {0.0, 0.3}, {w, 0.6}};
  r.full_amplitude_speed_mm_per_s = 30.0;
  s.roughness.push_back(r);
  TransitionCueSpec c;
  c.data = "feature";
  c.iso_value = 0.0;
  c.direction = {0.0, 1.0, 0.0};
  c.frequency_hz = 130.0;
  c.amplitude_N = 0.3;
  c.decay_time_ms = 100.0;
  s.transition_cues.push_back(c);
  return set;
}

}  // namespace vimg
