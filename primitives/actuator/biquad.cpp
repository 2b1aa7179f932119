#include "primitives/actuator/biquad.hpp"

#include <cmath>
#include <numbers>

namespace vimg {

std::complex<double> BiquadCoefficients::response(double frequency_hz, double sample_rate_hz) const {
  const double w = 2.0 * std::numbers::pi * frequency_hz / sample_rate_hz;
  const std::complex<double> z1 = std::polar(1.0, -w);  // z^-1
  const std::complex<double> z2 = z1 * z1;
  return (b0 + b1 * z1 + b2 * z2) / (1.0 + a1 * z1 + a2 * z2);
}

double BiquadCoefficients::gain_db(double frequency_hz, double sample_rate_hz) const {
  const double magnitude = std::abs(response(frequency_hz, sample_rate_hz));
  constexpr double kFloorDb = -400.0;
  return magnitude > 0.0 ? std::max(kFloorDb, 20.0 * std::log10(magnitude)) : kFloorDb;
}

BiquadCoefficients bilinear(const AnalogBiquad& s, double sample_rate_hz, double prewarp_hz) {
  const double wp = 2.0 * std::numbers::pi * prewarp_hz;
  const double k = wp / std::tan(wp / (2.0 * sample_rate_hz));
  const double k2 = k * k;
  // Substitute s = K (1 - z^-1)/(1 + z^-1) and multiply through by (1 + z^-1)^2.
  const double n0 = s.b2 * k2 + s.b1 * k + s.b0;
  const double n1 = 2.0 * (s.b0 - s.b2 * k2);
  const double n2 = s.b2 * k2 - s.b1 * k + s.b0;
  const double d0 = s.a2 * k2 + s.a1 * k + s.a0;
  const double d1 = 2.0 * (s.a0 - s.a2 * k2);
  const double d2 = s.a2 * k2 - s.a1 * k + s.a0;
  BiquadCoefficients c;
  c.b0 = n0 / d0;
  c.b1 = n1 / d0;
  c.b2 = n2 / d0;
  c.a1 = d1 / d0;
  c.a2 = d2 / d0;
  return c;
}

}  // namespace vimg
