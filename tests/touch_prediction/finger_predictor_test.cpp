// The touch predictor against closed forms (primitives/touch_prediction/finger_predictor.hpp):
// constant velocity is exact, constant acceleration stays within the bound the header derives
// from the weights, a still finger stays still, noise stays within s * G, and the history keeps
// its span whatever the event rate.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "primitives/touch_prediction/finger_predictor.hpp"
#include "primitives/touch_prediction/fitted_weights.hpp"

namespace vimg {
namespace {

using namespace touch_prediction;
constexpr TouchPredictionModel kModels[] = {TouchPredictionModel::none, TouchPredictionModel::linear,
                                            TouchPredictionModel::fitted};

// Weights at horizon h, interpolated as the predictor does (for the bounds).
std::array<double, kFittedLags> weights(const double (&table)[kFittedHorizons][kFittedLags], double h_s) {
  std::array<double, kFittedLags> w{};
  const double x = h_s / kFittedLag_s;
  const int j = std::min(static_cast<int>(std::floor(x)), kFittedHorizons - 1);
  const double a = x >= kFittedHorizons ? 1.0 : x - j;
  const double scale = x >= kFittedHorizons ? x / kFittedHorizons : 1.0;
  for (int k = 0; k < kFittedLags; ++k) {
    const double lower = j == 0 ? 0.0 : table[j - 1][k];
    const double upper = x >= kFittedHorizons ? table[kFittedHorizons - 1][k] : table[j][k];
    w[static_cast<std::size_t>(k)] = scale * ((1.0 - a) * lower + a * upper);
  }
  return w;
}

// e = v (-sum w_k k L - h) + a/2 (sum w_k k^2 L^2 - h^2), one axis.
double closed_form_error(const std::array<double, kFittedLags>& w, double v, double a, double h) {
  double m1 = 0.0, m2 = 0.0;
  for (int k = 1; k <= kFittedLags; ++k) {
    m1 += w[static_cast<std::size_t>(k - 1)] * k * kFittedLag_s;
    m2 += w[static_cast<std::size_t>(k - 1)] * k * k * kFittedLag_s * kFittedLag_s;
  }
  return v * (-m1 - h) + 0.5 * a * (m2 - h * h);
}

// A path sampled at `rate_hz` for `duration_s`, the last event at time t_end.
template <class Path>
FingerHistory history_of(Path path, double rate_hz, double duration_s, double t_end = 10.0) {
  FingerHistory h;
  const int n = static_cast<int>(std::lround(duration_s * rate_hz));
  for (int i = n; i >= 0; --i) {
    const double t = t_end - i / rate_hz;
    const auto [x, y] = path(t);
    add_finger_event(h, t, x, y);
  }
  return h;
}

TEST(FingerPredictor, ConstantVelocityIsExactForTheLinearAndFittedModels) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> speed(-400.0, 400.0), horizon(0.0, 0.3), rate(50.0, 1000.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double vx = speed(rng), vy = speed(rng), h = horizon(rng);
    const FingerHistory hist = history_of([&](double t) { return std::pair{3.0 + vx * t, -2.0 + vy * t}; }, rate(rng), 0.3);
    for (TouchPredictionModel m : {TouchPredictionModel::linear, TouchPredictionModel::fitted}) {
      const PredictedPosition p = predict_finger(hist, h, m);
      EXPECT_NEAR(p.x_mm, 3.0 + vx * (10.0 + h), 1e-6 * (1.0 + std::abs(vx))) << touch_prediction_model_name(m);
      EXPECT_NEAR(p.y_mm, -2.0 + vy * (10.0 + h), 1e-6 * (1.0 + std::abs(vy))) << touch_prediction_model_name(m);
    }
  }
}

TEST(FingerPredictor, ConstantAccelerationStaysWithinTheBoundOfTheTwoFilters) {
  // Events on the lag grid, so the interpolated displacements are the path's own.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> speed(-300.0, 300.0), accel(-3000.0, 3000.0), horizon(0.0, 0.25);
  for (int trial = 0; trial < 300; ++trial) {
    const double v = speed(rng), a = accel(rng), h = horizon(rng);
    // Velocity v and acceleration a at the last event, time 10 s.
    const FingerHistory hist = history_of(
        [&](double t) { const double u = t - 10.0; return std::pair{v * u + 0.5 * a * u * u, 0.0}; }, 120.0, 0.2);
    const double error = predict_finger(hist, h, TouchPredictionModel::fitted).x_mm - (v * h + 0.5 * a * h * h);
    const double bound = std::max(std::abs(closed_form_error(weights(kExactWeights, h), v, a, h)),
                                  std::abs(closed_form_error(weights(kFreeWeights, h), v, a, h)));
    EXPECT_LE(std::abs(error), bound * (1.0 + 1e-9) + 1e-9) << "v " << v << " a " << a << " h " << h;
  }
}

TEST(FingerPredictor, AStillFingerStaysStillUnderEveryModelAndHorizon) {
  const FingerHistory hist = history_of([](double) { return std::pair{12.5, 40.0}; }, 60.0, 1.0);
  for (TouchPredictionModel m : kModels) {
    for (double h : {0.0, 0.033, 0.1, 0.2, 1.0}) {
      const PredictedPosition p = predict_finger(hist, h, m);
      EXPECT_EQ(p.x_mm, 12.5);
      EXPECT_EQ(p.y_mm, 40.0);
    }
  }
}

TEST(FingerPredictor, NoiseOnAStillFingerStaysWithinSigmaTimesTheNoiseGain) {
  const double sigma = 0.3;
  for (double h : {0.033, 0.067, 0.1}) {
    const auto free = weights(kFreeWeights, h), exact = weights(kExactWeights, h);
    auto gain = [](const std::array<double, kFittedLags>& w) {
      double sum = 0.0, sum_abs = 0.0;
      for (double x : w) { sum += x; sum_abs += std::abs(x); }
      return std::abs(1.0 - sum) + sum_abs;
    };
    const double g = std::max(gain(free), gain(exact));
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, sigma);
    double sum2 = 0.0;
    const int trials = 4000;
    for (int trial = 0; trial < trials; ++trial) {
      const FingerHistory hist = history_of([&](double) { return std::pair{noise(rng), noise(rng)}; }, 60.0, 0.2);
      const PredictedPosition p = predict_finger(hist, h, TouchPredictionModel::fitted);
      sum2 += p.x_mm * p.x_mm + p.y_mm * p.y_mm;
    }
    const double rms_per_axis = std::sqrt(sum2 / (2.0 * trials));
    EXPECT_LE(rms_per_axis, sigma * g) << "h " << h;
    // The ridge of the fit keeps the gain small (docs/latency.md: 5.8 at 33 ms, 20.7 at 100 ms);
    // the unregularised least squares had about 150.
    EXPECT_LT(g, 25.0) << "the fitted filter amplifies noise more than its ridge should allow";
  }
}

TEST(FingerPredictor, SilenceFadesThePredictionBackToTheLastPosition) {
  const FingerHistory hist = history_of([](double t) { return std::pair{100.0 * t, 0.0}; }, 60.0, 0.2);
  const double last = 1000.0;
  for (TouchPredictionModel m : {TouchPredictionModel::linear, TouchPredictionModel::fitted}) {
    const double moving = predict_finger_at(hist, 10.0 + 0.02, 0.05, m).x_mm;
    EXPECT_NEAR(moving, last + 100.0 * 0.07, 1e-6);
    const double fading = predict_finger_at(hist, 10.0 + 0.075, 0.05, m).x_mm;
    EXPECT_NEAR(fading, last + 0.5 * 100.0 * 0.125, 1e-6);
    for (double silence : {0.1000001, 0.5, 100.0}) EXPECT_EQ(predict_finger_at(hist, 10.0 + silence, 0.05, m).x_mm, last);
  }
}

TEST(FingerPredictor, TheHistorySpansTheLagsEvenAtAThousandEventsASecond) {
  const FingerHistory hist = history_of([](double t) { return std::pair{50.0 * t, 0.0}; }, 1000.0, 0.5);
  const double span_s = hist.points[static_cast<std::size_t>(hist.newest)].time_s -
                        hist.points[static_cast<std::size_t>((hist.newest + 1) % FingerHistory::kHistoryCapacity)].time_s;
  EXPECT_EQ(hist.count, FingerHistory::kHistoryCapacity);
  EXPECT_GE(span_s, kFittedLags * kFittedLag_s);
}

TEST(FingerPredictor, EventsThatGoBackInTimeNeverReorderTheHistory) {
  FingerHistory hist;
  add_finger_event(hist, 1.0, 0.0, 0.0);
  add_finger_event(hist, 1.1, 1.0, 0.0);
  add_finger_event(hist, 0.5, 2.0, 0.0);
  EXPECT_EQ(last_finger_event_time_s(hist), 1.1);
  EXPECT_EQ(predict_finger(hist, 0.0, TouchPredictionModel::fitted).x_mm, 2.0);
}

TEST(FingerPredictor, ModelNamesReadBack) {
  for (TouchPredictionModel m : kModels) EXPECT_EQ(parse_touch_prediction_model(touch_prediction_model_name(m)), m);
  EXPECT_FALSE(parse_touch_prediction_model("lstm"));
  EXPECT_EQ(kDefaultTouchPredictionModel, TouchPredictionModel::fitted);
}

}  // namespace
}  // namespace vimg
