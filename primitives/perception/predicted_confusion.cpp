#include "primitives/perception/predicted_confusion.hpp"

#include <algorithm>

namespace vimg {

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
