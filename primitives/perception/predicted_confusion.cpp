#include "primitives/perception/predicted_confusion.hpp"

#include <algorithm>
#include <cmath>

namespace vimg {

PerceptionMatrix predicted_confusion(const PerceptionMatrix& similarity, const ChoiceModel& model) {
  const std::size_t n = similarity.size();
  const double tau = model.tau > 0.0 ? model.tau : ChoiceModel{}.tau;
  PerceptionMatrix p(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i) {
    // exp(-(d_ij - d_min) / tau): the same ratios, without underflow when every d is large.
    std::vector<double> distance(n, 1.0);
    for (std::size_t j = 0; j < n && j < similarity[i].size(); ++j) {
      const double s = similarity[i][j];
      distance[j] = 1.0 - (std::isnan(s) ? 0.0 : std::clamp(s, 0.0, 1.0));
    }
    const double nearest = *std::min_element(distance.begin(), distance.end());
    double total = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      p[i][j] = std::exp(-(distance[j] - nearest) / tau);
      total += p[i][j];
    }
    for (double& value : p[i]) value /= total;
  }
  return p;
}

std::vector<ConfusedPair> likely_confused_pairs(const PerceptionMatrix& confusion, const ChoiceModel& model) {
  std::vector<ConfusedPair> pairs;
  const std::size_t n = confusion.size();
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const double ab = b < confusion[a].size() ? confusion[a][b] : 0.0;
      const double ba = a < confusion[b].size() ? confusion[b][a] : 0.0;
      const double p = std::max(ab, ba);
      if (p >= model.likely_confused_p) pairs.push_back({a, b, p});
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const ConfusedPair& x, const ConfusedPair& y) { return x.p > y.p; });
  return pairs;
}

}  // namespace vimg
