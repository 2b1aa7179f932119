#include "primitives/touch_prediction/finger_predictor.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/touch_prediction/fitted_weights.hpp"
#include "primitives/touch_prediction/learned_predictor.hpp"

namespace vimg {

namespace {

using namespace touch_prediction;

constexpr int kCapacity = FingerHistory::kHistoryCapacity;
constexpr double kLinearMinInterval_s = 0.001;

const FingerHistory::Point& point(const FingerHistory& h, int age) {  // age 0: the newest
  return h.points[static_cast<std::size_t>((h.newest - age + kCapacity) % kCapacity)];
}

// d_k = p(t_n - k L) - p(t_n), k = 1..kFittedLags (see the header).
void lag_displacements(const FingerHistory& h, std::array<double, kFittedLags>& dx,
                       std::array<double, kFittedLags>& dy) {
  const FingerHistory::Point& now = point(h, 0);
  int age = 0;  // the segment [age + 1, age] (older, newer) holds the query time
  for (int k = 1; k <= kFittedLags; ++k) {
    const double tq = now.time_s - k * kFittedLag_s;
    while (age + 1 < h.count && point(h, age + 1).time_s > tq) ++age;
    double x = 0.0, y = 0.0;
    if (age + 1 >= h.count) {
      const FingerHistory::Point& first = point(h, h.count - 1);
      x = first.x_mm;
      y = first.y_mm;
    } else {
      const FingerHistory::Point& p0 = point(h, age + 1);
      const FingerHistory::Point& p1 = point(h, age);
      const double a = p1.time_s > p0.time_s ? (tq - p0.time_s) / (p1.time_s - p0.time_s) : 1.0;
      x = p0.x_mm + a * (p1.x_mm - p0.x_mm);
      y = p0.y_mm + a * (p1.y_mm - p0.y_mm);
    }
    dx[static_cast<std::size_t>(k - 1)] = x - now.x_mm;
    dy[static_cast<std::size_t>(k - 1)] = y - now.y_mm;
  }
}

// w(h) of one table: linear between the fitted horizons, w(0) = 0, scaled beyond the last.
void weights_at(const double (&table)[kFittedHorizons][kFittedLags], double horizon_s,
                std::array<double, kFittedLags>& w) {
  const double x = horizon_s / kFittedLag_s;
  if (x >= kFittedHorizons) {
    const double scale = x / kFittedHorizons;
    for (int k = 0; k < kFittedLags; ++k) w[static_cast<std::size_t>(k)] = scale * table[kFittedHorizons - 1][k];
    return;
  }
  const int j = static_cast<int>(std::floor(x));  // 0 .. kFittedHorizons - 1
  const double a = x - j;
  for (int k = 0; k < kFittedLags; ++k) {
    const double lower = j == 0 ? 0.0 : table[j - 1][k];
    w[static_cast<std::size_t>(k)] = (1.0 - a) * lower + a * table[j][k];
  }
}

// lambda of the blend (see the header).
double exactness(const std::array<double, kFittedLags>& dx, const std::array<double, kFittedLags>& dy) {
  double sum_kx = 0.0, sum_ky = 0.0, sum_kk = 0.0;
  for (int k = 1; k <= kFittedLags; ++k) {
    sum_kx += k * dx[static_cast<std::size_t>(k - 1)];
    sum_ky += k * dy[static_cast<std::size_t>(k - 1)];
    sum_kk += static_cast<double>(k) * k;
  }
  const double vx = -sum_kx / (kFittedLag_s * sum_kk);
  const double vy = -sum_ky / (kFittedLag_s * sum_kk);
  double residual2 = 0.0;
  for (int k = 1; k <= kFittedLags; ++k) {
    const double rx = dx[static_cast<std::size_t>(k - 1)] + vx * k * kFittedLag_s;
    const double ry = dy[static_cast<std::size_t>(k - 1)] + vy * k * kFittedLag_s;
    residual2 += rx * rx + ry * ry;
  }
  const double span_mm = std::hypot(vx, vy) * kFittedLags * kFittedLag_s;
  const double rho = std::sqrt(residual2 / kFittedLags) / (span_mm + kBlendFloor_mm);
  return std::exp(-rho / kBlendScale);
}

PredictedPosition fitted(const FingerHistory& h, double horizon_s) {
  std::array<double, kFittedLags> dx{}, dy{}, free{}, exact{};
  lag_displacements(h, dx, dy);
  weights_at(kFreeWeights, horizon_s, free);
  weights_at(kExactWeights, horizon_s, exact);
  const double lambda = exactness(dx, dy);
  const FingerHistory::Point& now = point(h, 0);
  PredictedPosition p{now.x_mm, now.y_mm};
  for (std::size_t k = 0; k < static_cast<std::size_t>(kFittedLags); ++k) {
    const double w = lambda * exact[k] + (1.0 - lambda) * free[k];
    p.x_mm += w * dx[k];
    p.y_mm += w * dy[k];
  }
  return p;
}

PredictedPosition linear(const FingerHistory& h, double horizon_s) {
  const FingerHistory::Point& now = point(h, 0);
  for (int age = 1; age < h.count; ++age) {
    const FingerHistory::Point& before = point(h, age);
    const double dt = now.time_s - before.time_s;
    if (dt >= kLinearMinInterval_s) {
      return {now.x_mm + (now.x_mm - before.x_mm) / dt * horizon_s,
              now.y_mm + (now.y_mm - before.y_mm) / dt * horizon_s};
    }
  }
  return {now.x_mm, now.y_mm};
}

}  // namespace

std::string_view touch_prediction_model_name(TouchPredictionModel model) {
  switch (model) {
    case TouchPredictionModel::none: return "none";
    case TouchPredictionModel::linear: return "linear";
    case TouchPredictionModel::fitted: return "fitted";
    case TouchPredictionModel::learned: return "learned";
  }
  return "fitted";
}

std::optional<TouchPredictionModel> parse_touch_prediction_model(std::string_view name) {
  for (TouchPredictionModel m : {TouchPredictionModel::none, TouchPredictionModel::linear, TouchPredictionModel::fitted,
                                 TouchPredictionModel::learned}) {
    if (name == touch_prediction_model_name(m)) return m;
  }
  return std::nullopt;
}

void reset_finger_history(FingerHistory& history) {
  history.newest = -1;
  history.count = 0;
}

bool finger_history_empty(const FingerHistory& history) { return history.count == 0; }

double last_finger_event_time_s(const FingerHistory& history) {
  return history.count == 0 ? 0.0 : point(history, 0).time_s;
}

void add_finger_event(FingerHistory& h, double time_s, double x_mm, double y_mm) {
  if (h.count > 0) time_s = std::max(time_s, point(h, 0).time_s);
  const bool replace = h.count >= 2 && point(h, 0).time_s - point(h, 1).time_s < FingerHistory::kMinSpacing_s;
  if (!replace) {
    h.newest = (h.newest + 1) % kCapacity;
    h.count = std::min(h.count + 1, kCapacity);
  }
  h.points[static_cast<std::size_t>(h.newest)] = {time_s, x_mm, y_mm};
}

PredictedPosition predict_finger(const FingerHistory& history, double horizon_s, TouchPredictionModel model) {
  if (history.count == 0) return {};
  const double h = std::isfinite(horizon_s) ? std::max(0.0, horizon_s) : 0.0;
  switch (model) {
    case TouchPredictionModel::none: break;
    case TouchPredictionModel::linear: return linear(history, h);
    case TouchPredictionModel::fitted: return fitted(history, h);
    case TouchPredictionModel::learned: return predict_learned(history, h);
  }
  const FingerHistory::Point& now = point(history, 0);
  return {now.x_mm, now.y_mm};
}

std::array<PredictedPosition, 2> predict_finger_pair(const FingerHistory& history, double first_horizon_s,
                                                     double second_horizon_s, TouchPredictionModel model) {
  if (model != TouchPredictionModel::learned || history.count == 0) {
    return {predict_finger(history, first_horizon_s, model), predict_finger(history, second_horizon_s, model)};
  }
  auto finite = [](double h) { return std::isfinite(h) ? std::max(0.0, h) : 0.0; };
  return predict_learned_pair(history, finite(first_horizon_s), finite(second_horizon_s));
}

PredictedPosition predict_finger_at(const FingerHistory& history, double now_s, double ahead_s,
                                    TouchPredictionModel model) {
  if (history.count == 0) return {};
  const FingerHistory::Point& last = point(history, 0);
  const double silence_s = std::max(0.0, now_s - last.time_s);
  const double fade = std::clamp((kSilenceStop_s - silence_s) / (kSilenceStop_s - kSilenceHold_s), 0.0, 1.0);
  if (fade <= 0.0) return {last.x_mm, last.y_mm};
  const PredictedPosition p = predict_finger(history, silence_s + ahead_s, model);
  return {last.x_mm + fade * (p.x_mm - last.x_mm), last.y_mm + fade * (p.y_mm - last.y_mm)};
}

}  // namespace vimg
