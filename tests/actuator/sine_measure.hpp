#pragma once
// Measures a filter's gain the way a bench would: a sine through it, RMS after it has settled.
#include <cmath>
#include <numbers>

namespace vimg::test {

// 20 log10(RMS out / RMS in) for a unit sine at frequency_hz, skipping settle_s, measuring over a
// whole number of periods of at least measure_s.
template <class Process>
double measured_gain_db(Process&& process, double frequency_hz, double rate_hz, double settle_s = 0.5,
                        double measure_s = 0.5) {
  const double w = 2.0 * std::numbers::pi * frequency_hz / rate_hz;
  const auto settle = static_cast<long>(settle_s * rate_hz);
  const double periods = std::ceil(measure_s * frequency_hz);
  const auto measure = static_cast<long>(std::lround(periods * rate_hz / frequency_hz));
  double in2 = 0.0;
  double out2 = 0.0;
  for (long n = 0; n < settle + measure; ++n) {
    const double x = std::sin(w * static_cast<double>(n));
    const double y = process(x);
    if (n >= settle) {
      in2 += x * x;
      out2 += y * y;
    }
  }
  return 10.0 * std::log10(out2 / in2);
}

}  // namespace vimg::test
