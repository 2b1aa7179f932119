#pragma once
// The fitted model written out again from its documented equations (docs/touch-prediction.md, "The
// predictor"; primitives/touch_prediction/finger_predictor.hpp), over the events a test fed in,
// for the tests to compare the predictor with:
//   d_k = p(t_n - k L) - p(t_n), k = 1..12, L = 1/120 s, p linear between events and equal to
//         the first event before it;
//   v_ls = -sum k d_k / (L sum k^2),  rho = rms_k |d_k + v_ls k L| / (|v_ls| 12 L + floor),
//   lambda = exp(-rho / scale),  p = p(t_n) + sum_k (lambda w_exact + (1 - lambda) w_free)(h) d_k,
// w(h) linear between the fitted horizons j L (w(0) = 0), and beyond the last one its weights
// times h / (24 L). Only the weight tables and the two constants come from fitted_weights.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "primitives/touch_prediction/finger_predictor.hpp"
#include "primitives/touch_prediction/fitted_weights.hpp"

namespace vimg::test {

using touch_prediction::kFittedHorizons;
using touch_prediction::kFittedLag_s;
using touch_prediction::kFittedLags;
using Lags = std::array<double, kFittedLags>;
using WeightTable = double[kFittedHorizons][kFittedLags];

struct TouchEvent {
  double time_s = 0.0;
  double x_mm = 0.0;
  double y_mm = 0.0;
};

inline FingerHistory history_of_events(const std::vector<TouchEvent>& events) {
  FingerHistory h;
  for (const TouchEvent& e : events) add_finger_event(h, e.time_s, e.x_mm, e.y_mm);
  return h;
}

// w(h): linear in h between the fitted horizons, 0 at h = 0, scaled beyond the last.
inline Lags fitted_weights_at(const WeightTable& table, double h_s) {
  Lags w{};
  const double x = h_s / kFittedLag_s;
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (x >= kFittedHorizons) {
      w[k] = x / kFittedHorizons * table[kFittedHorizons - 1][k];
    } else {
      const int j = static_cast<int>(std::floor(x));
      const double lower = j == 0 ? 0.0 : table[j - 1][k];
      w[k] = lower + (x - j) * (table[j][k] - lower);
    }
  }
  return w;
}

// p(t) of time-ordered events: linear between them, the first event before it.
inline TouchEvent position_at(const std::vector<TouchEvent>& events, double t_s) {
  auto after = std::upper_bound(events.begin(), events.end(), t_s,
                                [](double t, const TouchEvent& e) { return t < e.time_s; });
  if (after == events.begin()) return {t_s, events.front().x_mm, events.front().y_mm};
  if (after == events.end()) return {t_s, events.back().x_mm, events.back().y_mm};
  const TouchEvent& p0 = *(after - 1);
  const TouchEvent& p1 = *after;
  const double a = (t_s - p0.time_s) / (p1.time_s - p0.time_s);
  return {t_s, p0.x_mm + a * (p1.x_mm - p0.x_mm), p0.y_mm + a * (p1.y_mm - p0.y_mm)};
}

struct LagDisplacements {
  Lags dx{}, dy{};
};

inline LagDisplacements lag_displacements_of(const std::vector<TouchEvent>& events) {
  LagDisplacements d;
  const TouchEvent& now = events.back();
  for (int k = 1; k <= kFittedLags; ++k) {
    const TouchEvent p = position_at(events, now.time_s - k * kFittedLag_s);
    d.dx[static_cast<std::size_t>(k - 1)] = p.x_mm - now.x_mm;
    d.dy[static_cast<std::size_t>(k - 1)] = p.y_mm - now.y_mm;
  }
  return d;
}

struct Blend {
  double rho = 0.0;
  double lambda = 0.0;
};

inline Blend blend_of(const LagDisplacements& d) {
  double skx = 0.0, sky = 0.0, skk = 0.0;
  for (int k = 1; k <= kFittedLags; ++k) {
    skx += k * d.dx[static_cast<std::size_t>(k - 1)];
    sky += k * d.dy[static_cast<std::size_t>(k - 1)];
    skk += k * k;
  }
  const double vx = -skx / (kFittedLag_s * skk), vy = -sky / (kFittedLag_s * skk);
  double sum2 = 0.0;
  for (int k = 1; k <= kFittedLags; ++k) {
    const double rx = d.dx[static_cast<std::size_t>(k - 1)] + vx * k * kFittedLag_s;
    const double ry = d.dy[static_cast<std::size_t>(k - 1)] + vy * k * kFittedLag_s;
    sum2 += rx * rx + ry * ry;
  }
  Blend b;
  b.rho = std::sqrt(sum2 / kFittedLags) /
          (std::hypot(vx, vy) * kFittedLags * kFittedLag_s + touch_prediction::kBlendFloor_mm);
  b.lambda = std::exp(-b.rho / touch_prediction::kBlendScale);
  return b;
}

// p(t_n) + sum_k (lambda w_exact + (1 - lambda) w_free)(h) d_k, for a given lambda.
inline PredictedPosition fitted_prediction(const std::vector<TouchEvent>& events, double h_s, double lambda) {
  const LagDisplacements d = lag_displacements_of(events);
  const Lags free = fitted_weights_at(touch_prediction::kFreeWeights, h_s);
  const Lags exact = fitted_weights_at(touch_prediction::kExactWeights, h_s);
  PredictedPosition p{events.back().x_mm, events.back().y_mm};
  for (std::size_t k = 0; k < free.size(); ++k) {
    const double w = lambda * exact[k] + (1.0 - lambda) * free[k];
    p.x_mm += w * d.dx[k];
    p.y_mm += w * d.dy[k];
  }
  return p;
}

inline double sum_abs(const Lags& w) {
  double s = 0.0;
  for (double x : w) s += std::abs(x);
  return s;
}

}  // namespace vimg::test
