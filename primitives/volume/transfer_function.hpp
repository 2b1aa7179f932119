#pragma once
// A transfer function from a data value to a rendering parameter (omega, a period, an
// amplitude): piecewise linear through points sorted by value, constant beyond the end points.
#include <utility>
#include <vector>

namespace vimg {

struct TransferPoint {
  double value = 0.0;
  double output = 0.0;
  friend bool operator==(const TransferPoint&, const TransferPoint&) = default;
};

class TransferFunction {
 public:
  TransferFunction() = default;
  // Points must be sorted by strictly increasing value (storage checks this); an empty function
  // maps everything to 0.
  explicit TransferFunction(std::vector<TransferPoint> points) : points_(std::move(points)) {}
  double operator()(double value) const;
  const std::vector<TransferPoint>& points() const { return points_; }

 private:
  std::vector<TransferPoint> points_;
};

}  // namespace vimg
