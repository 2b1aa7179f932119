// The learned predictor at a stroke's onset and end (docs/touch-prediction.md, "What the tests hold it to"):
// on straight strokes that accelerate from rest, and on strokes that decelerate to rest, its mean
// error from the stroke's tenth event on is at most 1.25 times linear extrapolation's at 33, 67 and
// 100 ms. Seeded strokes: accelerations of 300-2000 mm/s^2 from rest for 0.5 s; peaks of 100-400 mm/s reached
// in 0.15-0.3 s, then decelerations of 300-1500 mm/s^2 to rest (judged while they decelerate);
// events at 60, 90 and 120 Hz with up to 2 ms of timing jitter; half of the strokes with positions
// rounded to a 12.72 px/mm panel's pixel, as the recorded traces are.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "primitives/touch_prediction/finger_predictor.hpp"

namespace vimg {
namespace {

constexpr double kPanelPxPerMm = 12.72;

struct Stroke {
  std::function<double(double)> along_mm;  // distance travelled at time t
  double heading_rad = 0.0;
  double rate_hz = 60.0;
  double duration_s = 0.5;
  double judged_from_s = 0.0, judged_to_s = 0.5;  // the span whose events are judged
  bool pixel_rounded = false;
};

std::array<double, 2> position(const Stroke& s, double t) {
  const double d = s.along_mm(t);
  return {10.0 + d * std::cos(s.heading_rad), 20.0 + d * std::sin(s.heading_rad)};
}

std::vector<Stroke> strokes(bool accelerating, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  std::vector<Stroke> out;
  for (int k = 0; k < 48; ++k) {
    Stroke s;
    s.rate_hz = std::array{60.0, 90.0, 120.0}[static_cast<std::size_t>(k % 3)];
    s.heading_rad = between(0.0, 2.0 * std::numbers::pi);
    s.pixel_rounded = k % 2 == 0;
    if (accelerating) {
      const double a = between(300.0, 2000.0);
      s.along_mm = [a](double t) { return 0.5 * a * t * t; };
    } else {
      const double rise_s = between(0.15, 0.3), peak = between(100.0, 400.0), stop_s = peak / between(300.0, 1500.0);
      s.along_mm = [=](double t) {
        const double up = std::clamp(t, 0.0, rise_s), down = std::clamp(t - rise_s, 0.0, stop_s);
        return 0.5 * peak / rise_s * up * up + peak * down - 0.5 * peak / stop_s * down * down;
      };
      s.duration_s = rise_s + stop_s + 0.05;
      s.judged_from_s = rise_s;
      s.judged_to_s = rise_s + stop_s;
    }
    out.push_back(s);
  }
  return out;
}

// Mean error (mm) of one model over every judged event from each stroke's tenth on.
double mean_error_mm(const std::vector<Stroke>& set, double horizon_s, TouchPredictionModel model, unsigned seed) {
  std::mt19937 rng(seed);  // the same timing jitter for every model
  std::uniform_real_distribution<double> jitter_s(-0.002, 0.002);
  double sum = 0.0;
  int n = 0;
  for (const Stroke& s : set) {
    FingerHistory h;
    double last_t = 0.0;
    for (int i = 0; i / s.rate_hz < s.duration_s; ++i) {
      const double t = std::max(last_t, i == 0 ? 0.0 : i / s.rate_hz + jitter_s(rng));
      last_t = t;
      std::array<double, 2> p = position(s, t);
      if (s.pixel_rounded) {
        for (double& v : p) v = std::round(v * kPanelPxPerMm) / kPanelPxPerMm;
      }
      add_finger_event(h, t, p[0], p[1]);
      if (i < 9 || t < s.judged_from_s || t >= s.judged_to_s) continue;
      const PredictedPosition predicted = predict_finger(h, horizon_s, model);
      const std::array<double, 2> target = position(s, t + horizon_s);
      sum += std::hypot(predicted.x_mm - target[0], predicted.y_mm - target[1]);
      ++n;
    }
  }
  EXPECT_GT(n, 500);
  return sum / n;
}

void expect_within_a_quarter_of_linear(bool accelerating) {
  const std::vector<Stroke> set = strokes(accelerating, accelerating ? 11u : 12u);
  for (double horizon_s : {1.0 / 30.0, 2.0 / 30.0, 0.1}) {
    const double learned = mean_error_mm(set, horizon_s, TouchPredictionModel::learned, 7u);
    const double linear = mean_error_mm(set, horizon_s, TouchPredictionModel::linear, 7u);
    EXPECT_LE(learned, 1.25 * linear) << "horizon " << horizon_s * 1000.0 << " ms: learned " << learned
                                      << " mm, linear " << linear << " mm";
    std::printf("%s, %.0f ms: learned %.3f mm, linear %.3f mm (%.2f)\n", accelerating ? "accelerating" : "decelerating",
                horizon_s * 1e3, learned, linear, learned / linear);
  }
}

TEST(StrokeOnset, AcceleratingFromRestWithinAQuarterOfLinearExtrapolation) { expect_within_a_quarter_of_linear(true); }

TEST(StrokeOnset, DeceleratingToRestWithinAQuarterOfLinearExtrapolation) { expect_within_a_quarter_of_linear(false); }

}  // namespace
}  // namespace vimg
