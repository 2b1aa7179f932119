#include "primitives/touch/line_shader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render_helper.hpp"

namespace vimg {
namespace {

using test::render;
using test::straight_path;
constexpr double kPi = std::numbers::pi;

// A vertical line at x = 0 from y = -20 mm to 20 mm; the finger crosses it along +x at speed v,
// starting 5 mm to the left. Returns the exact release time beta.
double release_time_s(double width_mm, double v, double start_m = -0.005) {
  return (0.5 * width_mm * 1e-3 - start_m) / v;
}
double entry_time_s(double width_mm, double v, double start_m = -0.005) {
  return (-0.5 * width_mm * 1e-3 - start_m) / v;
}

Line vertical_line(double frequency_hz, double damping, double gain = 1.0, double width_mm = 1.5) {
  return Line{0.0, -20.0, 0.0, 20.0, width_mm, frequency_hz, damping, gain};
}

struct Mode {
  double frequency_hz, damping;
};

class LineRingDown : public ::testing::TestWithParam<Mode> {};

TEST_P(LineRingDown, OscillatesAtTheDampedFrequency) {
  const Mode m = GetParam();
  const LineShader line(vertical_line(m.frequency_hz, m.damping), TouchContext{});
  const double v = 0.07;
  const double beta = release_time_s(1.5, v);
  const auto r = render(line, straight_path({-0.005, 0.001, 0}, {v, 0, 0}), beta + 1.0);
  const auto crossings = test::zero_crossings(r, beta, beta + 1.0);
  ASSERT_GE(crossings.size(), 4u);
  const double expected = m.frequency_hz * std::sqrt(1.0 - m.damping * m.damping);
  EXPECT_NEAR(test::crossing_frequency_hz(crossings), expected, 0.01 * expected);
}

TEST_P(LineRingDown, EnvelopeDecaysAtZetaOmegaN) {
  const Mode m = GetParam();
  const LineShader line(vertical_line(m.frequency_hz, m.damping), TouchContext{});
  const double v = 0.07;
  const double beta = release_time_s(1.5, v);
  const auto r = render(line, straight_path({-0.005, 0.001, 0}, {v, 0, 0}), beta + 1.0);
  const auto peaks = test::abs_peaks(r, beta + 1.0 / 8000.0, beta + 1.0);
  ASSERT_GE(peaks.size(), 3u);
  std::vector<double> t, log_value;
  for (const auto& p : peaks) {
    t.push_back(p.time_s);
    log_value.push_back(std::log(p.value));
  }
  const double expected = 2.0 * kPi * m.frequency_hz * m.damping;
  EXPECT_NEAR(-test::slope(t, log_value), expected, 0.05 * expected);
}

TEST_P(LineRingDown, StopsBelowMinus40dBThenExactSilenceAndInactive) {
  const Mode m = GetParam();
  const LineShader line(vertical_line(m.frequency_hz, m.damping, 0.9), TouchContext{});
  const double v = 0.2;  // above full speed: A0 = gain
  const double beta = release_time_s(1.5, v);
  const auto r = render(line, straight_path({-0.005, 0.001, 0}, {v, 0, 0}), beta + 1.5);
  const double expected_end = beta + std::log(100.0) / (2.0 * kPi * m.frequency_hz * m.damping);
  std::size_t last_nonzero = 0;
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    if (r.drive[k] != 0.0) last_nonzero = k;
  }
  EXPECT_NEAR(r.time_s[last_nonzero], expected_end, 1.0 / r.sample_rate_hz + 1e-9);
  // The last output is within one sample of the -40 dB point of the envelope.
  const double decay_per_sample = std::exp(2.0 * kPi * m.frequency_hz * m.damping / r.sample_rate_hz);
  EXPECT_LE(std::abs(r.drive[last_nonzero]), 0.9 * 0.01 * decay_per_sample);
  for (std::size_t k = last_nonzero + 1; k < r.drive.size(); ++k) {
    ASSERT_EQ(r.drive[k], 0.0);
    ASSERT_FALSE(r.active[k]);
  }
  EXPECT_TRUE(r.active[last_nonzero]);
}

TEST_P(LineRingDown, NoClickAtTheRelease) {
  // Phase is continuous across beta: no step between samples larger than the carrier's own slope.
  const Mode m = GetParam();
  const LineShader line(vertical_line(m.frequency_hz, m.damping), TouchContext{});
  const auto r = render(line, straight_path({-0.005, 0.001, 0}, {0.05, 0, 0}), 0.5);
  const double omega_d = 2.0 * kPi * m.frequency_hz * std::sqrt(1.0 - m.damping * m.damping);
  const double a0 = 0.5;  // v / fullSpeed
  const double largest_step = a0 * (omega_d + 2.0 * kPi * m.frequency_hz * m.damping) / r.sample_rate_hz;
  const double entry = entry_time_s(1.5, 0.05);
  for (std::size_t k = 1; k < r.drive.size(); ++k) {
    if (r.time_s[k - 1] < entry) continue;  // the onset is a pluck: a step is allowed there
    EXPECT_LE(std::abs(r.drive[k] - r.drive[k - 1]), largest_step * 1.001) << "t=" << r.time_s[k];
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, LineRingDown,
                         ::testing::Values(Mode{175.0, 0.05}, Mode{240.0, 0.02}, Mode{120.0, 0.15},
                                           Mode{200.0, 0.3}));

TEST(LineShader, ContactStimulusIsConstantAmplitudeProportionalToEntrySpeed) {
  TouchContext context;
  context.full_speed_m_per_s = 0.1;
  const LineShader line(vertical_line(175.0, 0.05, 1.0, 6.0), context);
  for (const double v : {0.01, 0.03, 0.06, 0.1, 0.3}) {
    const double alpha = entry_time_s(6.0, v);
    const double beta = release_time_s(6.0, v);
    const auto r = render(line, straight_path({-0.005, 0.0, 0}, {v, 0, 0}), beta);
    const double expected = std::min(1.0, v / 0.1);
    EXPECT_NEAR(test::max_abs(r, alpha, beta), expected, 0.01 * expected) << "v=" << v;
    const auto peaks = test::abs_peaks(r, alpha + 0.002, beta - 0.002);
    for (const auto& p : peaks) EXPECT_NEAR(p.value, expected, 0.005 * expected);
    for (std::size_t k = 0; k < r.drive.size(); ++k) {
      if (r.time_s[k] < alpha - 1e-9) {
        ASSERT_EQ(r.drive[k], 0.0);
      }
    }
  }
}

TEST(LineShader, FasterPluckRingsStrongerAndLonger) {
  const LineShader line(vertical_line(175.0, 0.05), TouchContext{});
  double previous_peak = 0.0;
  double previous_duration = 0.0;
  for (const double v : {0.01, 0.02, 0.05, 0.09}) {
    const double beta = release_time_s(1.5, v);
    const auto r = render(line, straight_path({-0.005, 0.0, 0}, {v, 0, 0}), beta + 0.5);
    const double peak = test::max_abs(r, beta, beta + 0.5);
    // Felt duration: time above a fixed absolute threshold (0.02, above every -40 dB end point).
    double last_loud = beta;
    for (std::size_t k = 0; k < r.drive.size(); ++k) {
      if (std::abs(r.drive[k]) > 0.02) last_loud = r.time_s[k];
    }
    EXPECT_GT(peak, previous_peak);
    EXPECT_GT(last_loud - beta, previous_duration);
    previous_peak = peak;
    previous_duration = last_loud - beta;
  }
}

TEST(LineShader, ReentryWhileRingingRestartsTheContactStimulus) {
  const LineShader line(vertical_line(175.0, 0.05), TouchContext{});
  // Cross at 0.02 m/s, come back 30 ms later at 0.09 m/s.
  const test::Path path = [](double t) {
    if (t < 0.3) return test::PathPoint{{-0.003 + 0.02 * t, 0, 0}, {0.02, 0, 0}, 1.0};
    const double x_turn = -0.003 + 0.02 * 0.3;  // 3 mm right of the line
    return test::PathPoint{{x_turn - 0.09 * (t - 0.3), 0, 0}, {-0.09, 0, 0}, 1.0};
  };
  const auto r = render(line, path, 0.4);
  const double second_entry = 0.3 + (0.003 - 0.00075) / 0.09;
  const double second_exit = 0.3 + (0.003 + 0.00075) / 0.09;
  EXPECT_LT(test::max_abs(r, second_entry - 0.01, second_entry - 1e-4), 0.2 * 0.5);  // ringing out
  EXPECT_NEAR(test::max_abs(r, second_entry, second_exit), 0.9, 0.01);  // a fresh pluck at 0.09/0.1
}

TEST(LineShader, FastCrossingInsideOneSampleStillRings) {
  // 1.5 mm band crossed at 30 m/s: 50 us in the band, shorter than the 125 us sample period.
  const LineShader line(vertical_line(175.0, 0.05), TouchContext{});
  const auto r = render(line, straight_path({-0.0021, 0.0, 0}, {30.0, 0, 0}), 0.1);
  EXPECT_GT(test::max_abs(r), 0.5);
}

TEST(LineShader, SilentWithoutContact) {
  const LineShader line(vertical_line(175.0, 0.05), TouchContext{});
  const auto r = render(line, straight_path({-0.005, 0.0201 + 0.00075, 0}, {0.1, 0, 0}), 0.1);
  for (std::size_t k = 0; k < r.drive.size(); ++k) {
    ASSERT_EQ(r.drive[k], 0.0);
    ASSERT_FALSE(r.active[k]);
  }
}

}  // namespace
}  // namespace vimg
