#include "primitives/perception/discrimination_choice.hpp"

#include <algorithm>
#include <limits>

namespace vimg {

namespace {

double non_negative(double x) { return std::isnan(x) || x < 0.0 ? 0.0 : x; }

double lapse(const DiscriminationConstants& k) {
  return std::isnan(k.lapse_rate) ? 0.0 : std::clamp(k.lapse_rate, 0.0, 1.0);
}

}  // namespace

double combined_distance_jnd(const CueDistances& d, const DiscriminationConstants& k) {
  double sum = 0.0;
  for (std::size_t c = 0; c < kCueCount; ++c) {
    const double term = non_negative(k.cue_weight[c]) * non_negative(d[c]);
    sum += term * term;
  }
  return std::sqrt(sum);
}

PerceptionMatrix discrimination_confusion(const CueMatrix& d, const DiscriminationConstants& k) {
  const std::size_t n = d.size();
  const double t = k.temperature_jnd;
  const double guess = lapse(k);
  // No default stands in for an invalid temperature: every cell says the constants were wrong.
  if (!valid_temperature_jnd(t)) return PerceptionMatrix(n, std::vector<double>(n, std::numeric_limits<double>::quiet_NaN()));
  PerceptionMatrix p(n, std::vector<double>(n, 0.0));
  std::vector<double> distance(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      distance[j] = (i == j || j >= d[i].size()) ? (i == j ? 0.0 : std::numeric_limits<double>::infinity())
                                                 : combined_distance_jnd(d[i][j], k);
    }
    // exp(-(D_ij - D_min) / T): the same ratios, without underflow when every D is large.
    const double nearest = *std::min_element(distance.begin(), distance.end());
    double total = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      p[i][j] = std::exp(-(distance[j] - nearest) / t);
      total += p[i][j];
    }
    for (double& value : p[i]) value = (1.0 - guess) * value / total + guess / static_cast<double>(n);
  }
  return p;
}

double two_alternative_confusion(double distance_jnd, const DiscriminationConstants& k) {
  CueDistances d{};
  d[0] = non_negative(distance_jnd);
  DiscriminationConstants unit = k;
  unit.cue_weight.fill(0.0);
  unit.cue_weight[0] = 1.0;
  const CueMatrix m = {{CueDistances{}, d}, {d, CueDistances{}}};
  return discrimination_confusion(m, unit)[0][1];
}

}  // namespace vimg
