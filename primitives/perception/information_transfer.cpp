#include "primitives/perception/information_transfer.hpp"

#include <cmath>
#include <cstddef>

namespace vimg {

double information_transfer_bits(const PerceptionMatrix& m) {
  const std::size_t n = m.size();
  if (n == 0) return 0.0;
  PerceptionMatrix rows;
  for (const auto& row : m) {
    double sum = 0.0;
    for (const double v : row) sum += v > 0.0 ? v : 0.0;
    if (!(sum > 0.0)) continue;
    std::vector<double> r;
    for (const double v : row) r.push_back(v > 0.0 ? v / sum : 0.0);
    rows.push_back(std::move(r));
  }
  if (rows.empty()) return 0.0;
  const double presented = static_cast<double>(rows.size());
  std::vector<double> chosen(rows.front().size(), 0.0);
  for (const auto& r : rows)
    for (std::size_t j = 0; j < r.size() && j < chosen.size(); ++j) chosen[j] += r[j] / presented;
  double bits = 0.0;
  for (const auto& r : rows)
    for (std::size_t j = 0; j < r.size() && j < chosen.size(); ++j)
      if (r[j] > 0.0) bits += r[j] / presented * std::log2(r[j] / chosen[j]);
  return bits > 0.0 ? bits : 0.0;
}

}  // namespace vimg
