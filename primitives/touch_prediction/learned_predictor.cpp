#include "primitives/touch_prediction/learned_predictor.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "primitives/touch_prediction/learned_weights.hpp"

namespace vimg {

namespace {

using namespace touch_prediction;

constexpr int kSteps = kLearnedPoints - 1;
static_assert(kLearnedPoints >= 4 && kLearnedInputs == 3 * kSteps + 2);

const FingerHistory::Point& point(const FingerHistory& h, int age) {  // age 0: the newest
  return h.points[static_cast<std::size_t>((h.newest - age + FingerHistory::kHistoryCapacity) % FingerHistory::kHistoryCapacity)];
}

// The newest kLearnedPoints points at least kLearnedMinStep_s apart, padded with the oldest.
std::array<FingerHistory::Point, kLearnedPoints> selected_points(const FingerHistory& h) {
  std::array<FingerHistory::Point, kLearnedPoints> p{};
  std::size_t n = 0;
  p[n++] = point(h, 0);
  for (int age = 1; age < h.count && n < p.size(); ++age) {
    const FingerHistory::Point& q = point(h, age);
    if (p[n - 1].time_s - q.time_s >= kLearnedMinStep_s) p[n++] = q;
  }
  for (; n < p.size(); ++n) p[n] = {p[n - 1].time_s - kLearnedNominalGap_s, p[n - 1].x_mm, p[n - 1].y_mm};
  return p;
}

// The first layer's sums over every input but the last two (the horizon and ln S), with its bias:
// what two horizons of one history share.
constexpr int kHorizonInput = kLearnedInputs - 2;

std::array<double, kLearnedWidth> first_layer_shared(const std::array<double, kLearnedInputs>& x) {
  std::array<double, kLearnedWidth> a1{};
  for (int j = 0; j < kLearnedWidth; ++j) a1[static_cast<std::size_t>(j)] = kLearnedB1[j];
  for (int i = 0; i < kHorizonInput; ++i) {
    const double xi = x[static_cast<std::size_t>(i)];
    for (int j = 0; j < kLearnedWidth; ++j) a1[static_cast<std::size_t>(j)] += xi * kLearnedW1[i][j];
  }
  return a1;
}

// The rest of the first layer (in the same order: the sums are those of one pass over every
// input), two ReLU layers, then kLearnedMaxGain * tanh: f in the stroke frame.
std::array<double, 2> forward(std::array<double, kLearnedWidth> a1, const std::array<double, kLearnedInputs>& x) {
  std::array<double, kLearnedWidth> a2{};
  for (int i = kHorizonInput; i < kLearnedInputs; ++i) {
    const double xi = x[static_cast<std::size_t>(i)];
    for (int j = 0; j < kLearnedWidth; ++j) a1[static_cast<std::size_t>(j)] += xi * kLearnedW1[i][j];
  }
  for (int j = 0; j < kLearnedWidth; ++j) a2[static_cast<std::size_t>(j)] = kLearnedB2[j];
  for (int i = 0; i < kLearnedWidth; ++i) {
    const double ai = std::max(a1[static_cast<std::size_t>(i)], 0.0);
    for (int j = 0; j < kLearnedWidth; ++j) a2[static_cast<std::size_t>(j)] += ai * kLearnedW2[i][j];
  }
  double z0 = kLearnedB3[0], z1 = kLearnedB3[1];
  for (int i = 0; i < kLearnedWidth; ++i) {
    const double ai = std::max(a2[static_cast<std::size_t>(i)], 0.0);
    z0 += ai * kLearnedW3[i][0];
    z1 += ai * kLearnedW3[i][1];
  }
  return {kLearnedMaxGain * std::tanh(z0), kLearnedMaxGain * std::tanh(z1)};
}

// The newest step's velocity, and the weight of continuing it: exp(-rho / kLearnedGateScale), rho the
// rms departure of the older steps' velocities from it, relative to its speed (1 at a constant velocity).
struct Gate {
  double weight = 0.0, vx = 0.0, vy = 0.0;
};

Gate velocity_gate(const std::array<double, kSteps>& sx, const std::array<double, kSteps>& sy,
                   const std::array<double, kSteps>& gap) {
  Gate g{0.0, sx[0] / gap[0], sy[0] / gap[0]};
  const double speed2 = g.vx * g.vx + g.vy * g.vy;
  if (speed2 <= 0.0) return g;
  double departure = 0.0;
  for (std::size_t j = 1; j < static_cast<std::size_t>(kSteps); ++j) {
    const double dx = sx[j] / gap[j] - g.vx, dy = sy[j] / gap[j] - g.vy;
    departure += dx * dx + dy * dy;
  }
  g.weight = std::exp(-std::sqrt(departure / (kSteps - 1) / speed2) / kLearnedGateScale);
  return g;
}

// The largest distance from the newest point to the points back to the newest one at least
// kLearnedRecent_s old (every point when none is).
double recent_reach_mm(const FingerHistory& h) {
  const FingerHistory::Point& now = point(h, 0);
  double largest2 = 0.0;
  for (int age = 1; age < h.count; ++age) {
    const FingerHistory::Point& p = point(h, age);
    const double dx = p.x_mm - now.x_mm, dy = p.y_mm - now.y_mm;
    largest2 = std::max(largest2, dx * dx + dy * dy);
    if (now.time_s - p.time_s >= kLearnedRecent_s) break;
  }
  return std::sqrt(largest2);
}

// Everything of one history that does not depend on the horizon.
struct Prepared {
  FingerHistory::Point now;
  bool still = false;  // every step zero: the finger is where it is at any horizon
  double scale_mm = 0.0, c = 1.0, s = 0.0;
  std::array<double, kLearnedInputs> x{};
  std::array<double, kLearnedWidth> a1{};
  Gate gate;
  double reach_mm = 0.0;
};

Prepared prepare(const FingerHistory& history) {
  const std::array<FingerHistory::Point, kLearnedPoints> p = selected_points(history);
  Prepared r;
  r.now = p[0];
  std::array<double, kSteps> sx{}, sy{}, gap{};
  double length_mm = 0.0;
  for (std::size_t j = 1; j < p.size(); ++j) {
    sx[j - 1] = p[j - 1].x_mm - p[j].x_mm;
    sy[j - 1] = p[j - 1].y_mm - p[j].y_mm;
    gap[j - 1] = p[j - 1].time_s - p[j].time_s;
    length_mm += std::sqrt(sx[j - 1] * sx[j - 1] + sy[j - 1] * sy[j - 1]);
  }
  r.still = length_mm == 0.0;
  if (r.still) return r;
  r.scale_mm = length_mm / kSteps;
  const double ux = r.now.x_mm - p[3].x_mm, uy = r.now.y_mm - p[3].y_mm;
  const double norm = std::sqrt(ux * ux + uy * uy);
  r.c = norm > 0.0 ? ux / norm : 1.0;
  r.s = norm > 0.0 ? uy / norm : 0.0;
  for (std::size_t j = 0; j < static_cast<std::size_t>(kSteps); ++j) {
    r.x[3 * j] = (r.c * sx[j] + r.s * sy[j]) / r.scale_mm;
    r.x[3 * j + 1] = (-r.s * sx[j] + r.c * sy[j]) / r.scale_mm;
    r.x[3 * j + 2] = std::clamp(gap[j] / kLearnedNominalGap_s - 1.0, -1.0, 3.0);
  }
  r.x[kLearnedInputs - 1] = std::clamp(std::log(r.scale_mm) / 2.0, -3.0, 2.0);
  r.a1 = first_layer_shared(r.x);
  r.gate = velocity_gate(sx, sy, gap);
  r.reach_mm = recent_reach_mm(history);
  return r;
}

PredictedPosition at_horizon(Prepared& r, double horizon_s) {
  if (r.still || horizon_s <= 0.0) return {r.now.x_mm, r.now.y_mm};
  r.x[kHorizonInput] = std::min(horizon_s, kLearnedHorizonRef_s) / kLearnedHorizonRef_s;
  const std::array<double, 2> f = forward(r.a1, r.x);
  const double gain = r.scale_mm * horizon_s / kLearnedHorizonRef_s;
  const double lx = f[0] * gain, ly = f[1] * gain;
  const Gate& g = r.gate;
  const double ox = g.weight * g.vx * horizon_s + (1.0 - g.weight) * (r.c * lx - r.s * ly);
  const double oy = g.weight * g.vy * horizon_s + (1.0 - g.weight) * (r.s * lx + r.c * ly);
  const double size = std::sqrt(ox * ox + oy * oy);
  const double limit = horizon_s * kLearnedReachPerSecond * r.reach_mm;
  const double shrink = size > limit ? limit / size : 1.0;
  return {r.now.x_mm + ox * shrink, r.now.y_mm + oy * shrink};
}

}  // namespace

PredictedPosition predict_learned(const FingerHistory& history, double horizon_s) {
  Prepared r = prepare(history);
  return at_horizon(r, horizon_s);
}

std::array<PredictedPosition, 2> predict_learned_pair(const FingerHistory& history, double first_horizon_s,
                                                      double second_horizon_s) {
  Prepared r = prepare(history);
  const PredictedPosition first = at_horizon(r, first_horizon_s);
  return {first, at_horizon(r, second_horizon_s)};
}

}  // namespace vimg
