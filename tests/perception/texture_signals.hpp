#pragma once
// Synthetic signals at 8 kHz in the manner of the three touch primitives rendered under a rubbing
// finger (DESIGN section 4): the finger crosses the feature every 0.8 s.
//   DOT:     a 175 Hz carrier while the finger is on the disc (30 ms), phase 0 at entry;
//   LINE:    a 175 Hz carrier while on the band (20 ms), then a ring-down exp(-zeta omega t) to -40 dB;
//   SURFACE: a periodic texture (period 2 mm at 100 mm/s: 50 Hz) while on the surface (0.5 s of 0.8 s).
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace vimg::test {

inline constexpr double kRateHz = 8000.0;
inline constexpr double kCrossingPeriodS = 0.8;
inline constexpr double kFirstCrossingS = 0.35;

inline std::vector<double> silence(double seconds) {
  return std::vector<double>(static_cast<std::size_t>(seconds * kRateHz), 0.0);
}

inline double time_since_crossing_s(std::size_t n) {
  const double t = static_cast<double>(n) / kRateHz - kFirstCrossingS;
  return t < 0.0 ? -1.0 : std::fmod(t, kCrossingPeriodS);
}

inline std::vector<double> dot_signal(double seconds, double gain = 1.0) {
  std::vector<double> x = silence(seconds);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = time_since_crossing_s(n);
    if (t >= 0.0 && t < 0.030) x[n] = gain * std::sin(2.0 * std::numbers::pi * 175.0 * t);
  }
  return x;
}

inline std::vector<double> line_signal(double seconds, double gain = 1.0) {
  const double omega = 2.0 * std::numbers::pi * 175.0;
  const double zeta = 0.02;
  const double band_s = 0.020;
  const double ring_s = std::log(100.0) / (zeta * omega);  // to -40 dB
  std::vector<double> x = silence(seconds);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = time_since_crossing_s(n);
    if (t < 0.0 || t >= band_s + ring_s) continue;
    const double envelope = t < band_s ? 1.0 : std::exp(-zeta * omega * (t - band_s));
    x[n] = gain * envelope * std::sin(omega * t);
  }
  return x;
}

inline std::vector<double> surface_signal(double seconds, double gain = 0.8, double texture_hz = 50.0) {
  std::vector<double> x = silence(seconds);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = time_since_crossing_s(n);
    if (t >= 0.0 && t < 0.5) x[n] = gain * std::sin(2.0 * std::numbers::pi * texture_hz * t);
  }
  return x;
}

// Continuous sum of sines (amplitude, frequency) over the whole signal.
struct Partial {
  double amplitude = 0.0;
  double frequency_hz = 0.0;
};
inline std::vector<double> partials_signal(double seconds, std::initializer_list<Partial> partials) {
  std::vector<double> x = silence(seconds);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = static_cast<double>(n) / kRateHz;
    for (const Partial& p : partials) x[n] += p.amplitude * std::sin(2.0 * std::numbers::pi * p.frequency_hz * t);
  }
  return x;
}

}  // namespace vimg::test
