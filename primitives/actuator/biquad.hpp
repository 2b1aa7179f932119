#pragma once
// One second-order section: the analog prototype, its bilinear transform with prewarping, the
// digital filter run sample by sample, and its magnitude response from the same coefficients.
//
// Threads: Biquad is a value type with no shared state; process() never allocates, locks or
// throws, so one instance may run on a real-time thread (one thread per instance).
#include <complex>

namespace vimg {

// H(s) = (b2 s^2 + b1 s + b0) / (a2 s^2 + a1 s + a0), s in rad/s.
struct AnalogBiquad {
  double b2 = 0.0;
  double b1 = 0.0;
  double b0 = 1.0;
  double a2 = 0.0;
  double a1 = 0.0;
  double a0 = 1.0;
};

// H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2). The default is the identity.
struct BiquadCoefficients {
  double b0 = 1.0;
  double b1 = 0.0;
  double b2 = 0.0;
  double a1 = 0.0;
  double a2 = 0.0;

  // H(e^{j 2 pi f / fs}).
  std::complex<double> response(double frequency_hz, double sample_rate_hz) const;
  // 20 log10 |H|; a very low finite number (-400 dB) where |H| is 0.
  double gain_db(double frequency_hz, double sample_rate_hz) const;
  void scale(double gain) {
    b0 *= gain;
    b1 *= gain;
    b2 *= gain;
  }
};

// The bilinear transform s = K (1 - z^-1) / (1 + z^-1) with K = w_p / tan(w_p / (2 fs)),
// w_p = 2 pi prewarp_hz: the digital response at prewarp_hz equals the analog one exactly.
// prewarp_hz must lie in (0, fs/2).
BiquadCoefficients bilinear(const AnalogBiquad& analog, double sample_rate_hz, double prewarp_hz);

// Transposed direct form II, double state.
class Biquad {
 public:
  Biquad() = default;
  explicit Biquad(const BiquadCoefficients& c) : c_(c) {}

  double process(double x) noexcept {
    const double y = c_.b0 * x + s1_;
    s1_ = c_.b1 * x - c_.a1 * y + s2_;
    s2_ = c_.b2 * x - c_.a2 * y;
    return y;
  }
  void reset() noexcept { s1_ = s2_ = 0.0; }
  const BiquadCoefficients& coefficients() const { return c_; }

 private:
  BiquadCoefficients c_;
  double s1_ = 0.0;
  double s2_ = 0.0;
};

}  // namespace vimg
