#include "primitives/volume/transfer_function.hpp"

#include <algorithm>

namespace vimg {

double TransferFunction::operator()(double value) const {
  if (points_.empty()) return 0.0;
  if (!(value > points_.front().value)) return points_.front().output;  // also NaN
  if (value >= points_.back().value) return points_.back().output;
  const auto upper = std::upper_bound(points_.begin(), points_.end(), value,
                                      [](double v, const TransferPoint& p) { return v < p.value; });
  const auto lower = upper - 1;
  const double t = (value - lower->value) / (upper->value - lower->value);
  return lower->output + t * (upper->output - lower->output);
}

}  // namespace vimg
