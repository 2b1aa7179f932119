#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "primitives/cues/roughness_shader.hpp"
#include "primitives/cues/transition_cue_shader.hpp"
#include "render_helper.hpp"

namespace vimg {
namespace {

using test::render;
using test::straight_path;
constexpr double kPi = std::numbers::pi;

// --- Roughness ---------------------------------------------------------------------------------

TEST(RoughnessShader, PhaseFollowsDistanceSoFrequencyIsSpeedTimesOmegaOverTwoPi) {
  const double omega = 2.0 * kPi / 0.0025;  // 2.5 mm period
  RoughnessParams params;
  params.amplitude_N = 0.6;
  params.full_amplitude_speed_m_per_s = 0.03;
  const RoughnessShader shader(std::make_shared<ConstantSpatialFrequency>(omega), params);
  for (const double v : {0.05, 0.1, 0.3, 0.8}) {
    // Diagonal motion in 3-D: the distance, not one coordinate, drives the phase.
    const Vec3 velocity = Vec3{1, 2, 2} * (v / 3.0);
    const auto r = render(shader, straight_path({0, 0, 0}, velocity), 0.4, 4000.0, {0, 0, 1}, 1.0);
    const double expected = v * omega / (2.0 * kPi);
    EXPECT_NEAR(test::crossing_frequency_hz(test::zero_crossings(r, 0, 1)), expected, 0.01 * expected) << v;
    EXPECT_NEAR(test::max_abs(r), 0.6, 0.6 * 0.02);
  }
}

TEST(RoughnessShader, AmplitudeIsZeroAtRestAndLinearUpToFullSpeed) {
  RoughnessParams params;
  params.amplitude_N = 0.5;
  params.full_amplitude_speed_m_per_s = 0.04;
  const RoughnessShader shader(std::make_shared<ConstantSpatialFrequency>(2.0 * kPi / 0.0004), params);
  for (const double v : {0.005, 0.01, 0.02, 0.04, 0.1}) {
    const auto r = render(shader, straight_path({0, 0, 0}, {v, 0, 0}), 0.2, 8000.0);
    const double expected = 0.5 * std::min(1.0, v / 0.04);
    EXPECT_NEAR(test::max_abs(r), expected, expected * 0.01) << v;
  }
  const auto still = render(shader, straight_path({0.01, 0.02, 0.03}, {0, 0, 0}), 0.1);
  EXPECT_EQ(test::max_abs(still), 0.0);
}

class StepFrequency final : public SpatialFrequencyField {
 public:
  double omega_rad_per_m(const Vec3& p) const override { return p.x < 0.01 ? 2.0 * kPi / 0.002 : 2.0 * kPi / 0.001; }
};

TEST(RoughnessShader, SpatialFrequencyComesFromTheField) {
  RoughnessParams params;
  params.direction = {1, 0, 0};
  const RoughnessShader shader(std::make_shared<StepFrequency>(), params);
  const auto r = render(shader, straight_path({0, 0, 0}, {0.1, 0, 0}), 0.2, 8000.0, {1, 0, 0});
  // x < 10 mm for t < 0.1 s: 2 mm period (50 Hz), then 1 mm (100 Hz).
  EXPECT_NEAR(test::crossing_frequency_hz(test::zero_crossings(r, 0.01, 0.095)), 50.0, 0.5);
  EXPECT_NEAR(test::crossing_frequency_hz(test::zero_crossings(r, 0.105, 0.2)), 100.0, 1.0);
}

// --- Transition cue ----------------------------------------------------------------------------

// A nonlinear but monotonic field along z whose iso-surface value 0 is the plane z = plane_m.
class PlaneField final : public ScalarField {
 public:
  explicit PlaneField(double plane_m) : plane_m_(plane_m) {}
  double value(const Vec3& p) const override { return std::sinh(300.0 * (p.z - plane_m_)) + 0.1 * (p.z - plane_m_); }

 private:
  double plane_m_;
};

struct CueRun {
  test::Rendered r;
  double crossing_time_s;  // when the straight path truly crosses the plane
};

CueRun run_cue(const TransitionCueShader& cue, double plane_m, double speed, double rate_hz, double duration_s) {
  const double start = plane_m - 0.0123;
  CueRun run;
  run.r = render(cue, straight_path({0.001, 0.002, start}, {0, 0, speed}), duration_s, rate_hz);
  run.crossing_time_s = 0.0123 / speed;
  return run;
}

TEST(TransitionCueShader, RingsAtOmegaDAndDecaysAtBeta) {
  const double plane = 0.0371;
  for (const double tau : {0.1, 0.03}) {
    TransitionCueParams params;  // 130 Hz, 0.3 N
    params.decay_time_s = tau;
    const TransitionCueShader cue(std::make_shared<PlaneField>(plane), params);
    const auto run = run_cue(cue, plane, 0.5, 8000.0, 0.9);
    const double tc = run.crossing_time_s;
    const double beta = 1.0 / tau;
    const double omega0 = 2.0 * kPi * 130.0;
    const double omega_d = std::sqrt(omega0 * omega0 - beta * beta);
    const auto crossings = test::zero_crossings(run.r, tc + 1e-4, tc + 3.0 * tau);
    EXPECT_NEAR(2.0 * kPi * test::crossing_frequency_hz(crossings), omega_d, 0.01 * omega_d);
    const auto peaks = test::abs_peaks(run.r, tc, tc + 3.0 * tau);
    std::vector<double> t, log_value;
    for (const auto& p : peaks) {
      t.push_back(p.time_s);
      log_value.push_back(std::log(p.value));
    }
    ASSERT_GE(peaks.size(), 3u);
    EXPECT_NEAR(-test::slope(t, log_value), beta, 0.05 * beta);
    EXPECT_NEAR(peaks.front().value, 0.3, 0.3 * 0.1);
  }
}

TEST(TransitionCueShader, OnsetIsAtThePlaneWhateverTheSampleRate) {
  // At 0.5 m/s a 1 kHz loop moves 0.5 mm per sample; the onset must still sit within 0.1 mm of
  // the plane. Measured from the output: the first zero crossing after onset is at t_c + pi/omega_d.
  const double plane = 0.0371;
  TransitionCueParams params;
  const TransitionCueShader cue(std::make_shared<PlaneField>(plane), params);
  const double omega0 = 2.0 * kPi * 130.0;
  const double omega_d = std::sqrt(omega0 * omega0 - 100.0);
  for (const double rate : {1000.0, 2000.0, 8000.0}) {
    const double speed = 0.5;
    const auto run = run_cue(cue, plane, speed, rate, 0.2);
    const auto crossings = test::zero_crossings(run.r, 0.0, 1.0);
    ASSERT_FALSE(crossings.empty());
    const double onset_s = crossings.front() - kPi / omega_d;
    const double onset_z = plane - 0.0123 + speed * onset_s;
    EXPECT_NEAR(onset_z, plane, 1e-4) << "rate " << rate;
    // Nothing before the crossing.
    for (std::size_t k = 0; k < run.r.drive.size(); ++k) {
      if (run.r.time_s[k] < run.crossing_time_s) {
        ASSERT_EQ(run.r.drive[k], 0.0);
      }
    }
  }
}

TEST(TransitionCueShader, CrossingPointIsLocatedToANanometre) {
  const double plane = 0.0371;
  const TransitionCueShader cue(std::make_shared<PlaneField>(plane), TransitionCueParams{});
  ShaderState state;
  cue.begin_contact(state);
  InteractionState s;
  s.previous_position_m = {0.0, 0.0, plane - 0.0003};
  s.position_m = {0.0, 0.0, plane + 0.0002};
  s.time_s = 1.0;
  s.dt_s = 0.001;
  cue.force_N(s, state);
  Vec3 where;
  double when = 0.0;
  ASSERT_TRUE(cue.last_crossing(state, where, when));
  EXPECT_NEAR(where.z, plane, 1e-9);
  EXPECT_NEAR(when, 1.0 - 0.001 * (1.0 - 0.6), 1e-9);
}

TEST(TransitionCueShader, EndsWithExactSilenceAndFiresAgainOnTheWayBack) {
  const double plane = 0.02;
  TransitionCueParams params;
  params.decay_time_s = 0.02;
  const TransitionCueShader cue(std::make_shared<PlaneField>(plane), params);
  // Cross upward at t = 0.1 s, come back down across the plane at t = 0.5 s.
  const test::Path path = [](double t) {
    const double z = t < 0.3 ? 0.01 + 0.1 * t : 0.04 - 0.1 * (t - 0.3);
    return test::PathPoint{{0, 0, z}, {0, 0, t < 0.3 ? 0.1 : -0.1}, 1.0};
  };
  const auto r = render(cue, path, 0.7);
  const double end_first = 0.1 + std::log(100.0) * 0.02;
  EXPECT_GT(test::max_abs(r, 0.1, 0.12), 0.2);
  EXPECT_EQ(test::max_abs(r, end_first + 1e-3, 0.499), 0.0);
  EXPECT_GT(test::max_abs(r, 0.5, 0.52), 0.2);
  EXPECT_LT(test::max_abs(r, 0.1, 0.7), 0.3 + 1e-12);
}

}  // namespace
}  // namespace vimg
