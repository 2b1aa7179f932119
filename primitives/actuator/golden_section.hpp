#pragma once
// The maximum of a unimodal function on [a, b] by golden-section search: where it is, to about
// (b - a) * 0.618^iterations.
#include <cmath>

namespace vimg {

template <class Function>
double golden_section_argmax(Function&& f, double a, double b, int iterations = 60) {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < iterations; ++i) {
    const double c = b - ratio * (b - a);
    const double d = a + ratio * (b - a);
    if (f(c) > f(d)) {
      b = d;
    } else {
      a = c;
    }
  }
  return (a + b) / 2.0;
}

}  // namespace vimg
