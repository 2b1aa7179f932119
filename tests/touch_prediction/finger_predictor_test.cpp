// The touch predictor against closed forms (primitives/touch_prediction/finger_predictor.hpp):
// constant velocity is exact, constant acceleration stays within the bound the header derives
// from the weights, a still finger stays still, the blend follows rho and lambda of the history,
// noise comes out as sigma times the L2 norm of the model's response, and the history keeps its
// span whatever the event rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "every_model.hpp"
#include "fitted_reference.hpp"
#include "sampled_history.hpp"

namespace vimg {
namespace {

using namespace touch_prediction;
using test::fitted_weights_at;
using test::history_of;
using test::Lags;
using test::TouchEvent;

// e = v (-sum w_k k L - h) + a/2 (sum w_k k^2 L^2 - h^2), one axis.
double closed_form_error(const Lags& w, double v, double a, double h) {
  double m1 = 0.0, m2 = 0.0;
  for (int k = 1; k <= kFittedLags; ++k) {
    m1 += w[static_cast<std::size_t>(k - 1)] * k * kFittedLag_s;
    m2 += w[static_cast<std::size_t>(k - 1)] * k * k * kFittedLag_s * kFittedLag_s;
  }
  return v * (-m1 - h) + 0.5 * a * (m2 - h * h);
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
    const double bound = std::max(std::abs(closed_form_error(fitted_weights_at(kExactWeights, h), v, a, h)),
                                  std::abs(closed_form_error(fitted_weights_at(kFreeWeights, h), v, a, h)));
    EXPECT_LE(std::abs(error), bound * (1.0 + 1e-9) + 1e-9) << "v " << v << " a " << a << " h " << h;
  }
}

TEST(FingerPredictor, AStillFingerStaysStillUnderEveryModelAndHorizon) {
  const FingerHistory hist = history_of([](double) { return std::pair{12.5, 40.0}; }, 60.0, 1.0);
  for (TouchPredictionModel m : test::every_touch_prediction_model()) {
    for (double h : {0.0, 0.033, 0.1, 0.2, 1.0}) {
      const PredictedPosition p = predict_finger(hist, h, m);
      EXPECT_EQ(p.x_mm, 12.5);
      EXPECT_EQ(p.y_mm, 40.0);
    }
  }
}

// The L2 norm of a model's response to the events' noises on a still finger with events every
// interval_s, n of them: the prediction's error is sum_i c_i n_i, c_i the prediction for a unit
// displacement of event i alone, so white noise of standard deviation sigma on every event gives an
// error of standard deviation sigma ||c||_2 on each axis (not the L1 norm: that bounds the worst
// case, not the spread).
//   none:   c = (1);
//   linear: c = (1 + h / dt, -h / dt), the last two events;
//   fitted: the free filter's response (on a still noisy finger rho is large and lambda near 0),
//           through the reference's interpolation and weights.
double noise_response_norm(TouchPredictionModel model, double h_s, double interval_s, int n) {
  switch (model) {
    case TouchPredictionModel::none: return 1.0;
    case TouchPredictionModel::linear: return std::hypot(1.0 + h_s / interval_s, h_s / interval_s);
    default: break;
  }
  std::vector<TouchEvent> events(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) events[static_cast<std::size_t>(i)].time_s = 10.0 - (n - 1 - i) * interval_s;
  double sum2 = 0.0;
  for (TouchEvent& e : events) {
    e.x_mm = 1.0;
    const double c = test::fitted_prediction(events, h_s, 0.0).x_mm;
    sum2 += c * c;
    e.x_mm = 0.0;
  }
  return std::sqrt(sum2);
}

TEST(FingerPredictor, NoiseComesOutAsSigmaTimesTheL2NormOfTheModelsResponse) {
  const double sigma = 0.3, x0 = 12.0, y0 = 40.0;
  const int trials = 4000;
  for (double rate_hz : {120.0, 60.0}) {
    const int n = static_cast<int>(std::lround(0.2 * rate_hz)) + 1;
    for (double h : {1.0 / 120.0, 0.033, 0.067, 0.1}) {
      for (TouchPredictionModel m : {TouchPredictionModel::none, TouchPredictionModel::linear, TouchPredictionModel::fitted}) {
        const double norm = noise_response_norm(m, h, 1.0 / rate_hz, n);
        std::mt19937 rng(3);
        std::normal_distribution<double> noise(0.0, sigma);
        double sum2 = 0.0, largest_lambda = 0.0;
        for (int trial = 0; trial < trials; ++trial) {
          std::vector<TouchEvent> events;
          for (int i = 0; i < n; ++i) events.push_back({10.0 - (n - 1 - i) / rate_hz, x0 + noise(rng), y0 + noise(rng)});
          const PredictedPosition p = predict_finger(test::history_of_events(events), h, m);
          sum2 += (p.x_mm - x0) * (p.x_mm - x0) + (p.y_mm - y0) * (p.y_mm - y0);
          largest_lambda = std::max(largest_lambda, test::blend_of(test::lag_displacements_of(events)).lambda);
        }
        const double rms_per_axis = std::sqrt(sum2 / (2.0 * trials));
        // 8000 draws: the rms is within about 1 % of its expectation; 10 % leaves no chance failure.
        EXPECT_NEAR(rms_per_axis / (sigma * norm), 1.0, 0.10)
            << touch_prediction_model_name(m) << " h " << h << " at " << rate_hz << " Hz: rms " << rms_per_axis
            << " mm, sigma ||c|| " << sigma * norm << " mm";
        // The still noisy finger gives the free filter: lambda stays below 1e-3 (rho > 0.07), which
        // moves ||c|| by less than 0.1 %.
        ASSERT_LT(largest_lambda, 1e-3);
      }
    }
  }
}

// Irregular histories on arcs of every curvature, with and without jitter: the fitted prediction is
// the documented blend, with lambda = exp(-rho / 0.01) of that history (computed here from the
// equations), and the lambda it applied, read back from where it lies between the two filters'
// predictions, is that lambda.
TEST(FingerPredictor, TheBlendIsLambdaOfRhoOnIrregularHistories) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int blended = 0, mostly_exact = 0, mostly_free = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const double radius_mm = 5.0 * std::pow(2000.0, unit(rng)), speed = 30.0 + 300.0 * unit(rng);
    const double jitter_mm = trial % 3 == 0 ? 0.03 * unit(rng) : 0.0, h = 0.3 * unit(rng);
    const double duration_s = 0.05 + 0.15 * unit(rng);
    std::vector<TouchEvent> events;
    for (double t = 3.0; t < 3.0 + duration_s && events.size() < 60; t += 0.003 + 0.017 * unit(rng)) {
      const double angle = speed * t / radius_mm;
      events.push_back({t, radius_mm * std::cos(angle) + jitter_mm * (unit(rng) - 0.5),
                        radius_mm * std::sin(angle) + jitter_mm * (unit(rng) - 0.5)});
    }
    const double lambda = test::blend_of(test::lag_displacements_of(events)).lambda;
    const PredictedPosition p = predict_finger(test::history_of_events(events), h, TouchPredictionModel::fitted);
    const PredictedPosition expected = test::fitted_prediction(events, h, lambda);
    EXPECT_NEAR(p.x_mm, expected.x_mm, 1e-9 * (1.0 + std::abs(expected.x_mm))) << "trial " << trial << " lambda " << lambda;
    EXPECT_NEAR(p.y_mm, expected.y_mm, 1e-9 * (1.0 + std::abs(expected.y_mm))) << "trial " << trial << " lambda " << lambda;
    const PredictedPosition exact = test::fitted_prediction(events, h, 1.0), free = test::fitted_prediction(events, h, 0.0);
    const double ex = exact.x_mm - free.x_mm, ey = exact.y_mm - free.y_mm, spread2 = ex * ex + ey * ey;
    if (spread2 < 1e-4) continue;  // the two filters agree within 0.01 mm: lambda cannot be read back
    const double applied = ((p.x_mm - free.x_mm) * ex + (p.y_mm - free.y_mm) * ey) / spread2;
    EXPECT_NEAR(applied, lambda, 1e-6) << "trial " << trial;
    blended += lambda > 0.1 && lambda < 0.9;
    mostly_exact += lambda >= 0.9;
    mostly_free += lambda <= 0.1;
  }
  // The histories covered the whole blend, so an exactness stuck anywhere fails above.
  EXPECT_GE(blended, 50);
  EXPECT_GE(mostly_exact, 50);
  EXPECT_GE(mostly_free, 50);
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

TEST(FingerPredictor, ModelNamesReadBackAndTheDefaultIsOneOfThem) {
  const std::vector<TouchPredictionModel> models = test::every_touch_prediction_model();
  for (TouchPredictionModel m : {TouchPredictionModel::none, TouchPredictionModel::linear, TouchPredictionModel::fitted}) {
    EXPECT_NE(std::find(models.begin(), models.end(), m), models.end()) << touch_prediction_model_name(m);
  }
  EXPECT_NE(std::find(models.begin(), models.end(), kDefaultTouchPredictionModel), models.end());
  EXPECT_FALSE(parse_touch_prediction_model("lstm"));
}

}  // namespace
}  // namespace vimg
