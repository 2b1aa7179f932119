#pragma once
// The Hann window of the perception code, in one place: the power spectrum's frames
// (power_spectrum.cpp), the envelopes' smoothing (discrimination_cues.cpp) and the channels'
// filters (channel_levels.cpp) each sample it in their own way.
//   hann(x) = 0.5 + 0.5 cos(pi x) for |x| < 1, else 0; x is the distance from the centre in
//   half-widths. A window of n samples numbered from 0: x = 2 (i + offset) / n - 1, where offset 0
//   is the periodic window of spectral analysis and offset 0.5 the one centred on its samples.
// Threads: pure.
#include <cmath>
#include <cstddef>
#include <numbers>

namespace vimg {

inline double hann(double x) { return std::abs(x) < 1.0 ? 0.5 + 0.5 * std::cos(std::numbers::pi * x) : 0.0; }

// Sample i of an n-sample window (see above for `offset`).
inline double hann_sample(std::size_t i, std::size_t n, double offset) {
  return hann(2.0 * (static_cast<double>(i) + offset) / static_cast<double>(n) - 1.0);
}

}  // namespace vimg
