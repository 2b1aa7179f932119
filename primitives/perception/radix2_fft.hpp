#pragma once
// The iterative radix-2 decimation-in-time FFT shared by the 512-point DCT of ST-SIM
// (block_dct.cpp) and the 4096-point power spectrum of the discrimination model
// (power_spectrum.cpp): in place over N = re.size() points (a power of two) already placed in
// bit-reversed order (plan.bit_reversed[i]: where sample i goes).
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <vector>

namespace vimg::detail {

struct Radix2Plan {
  std::vector<double> twiddle_re;          // twiddle_re[j] + i twiddle_im[j] = exp(-2 pi i j / N), j < N / 2
  std::vector<double> twiddle_im;
  std::vector<std::size_t> bit_reversed;   // i with its log2(N) bits reversed
};

// n: a power of two.
inline Radix2Plan radix2_plan(std::size_t n) {
  Radix2Plan plan;
  int bits = 0;
  while ((std::size_t{1} << bits) < n) ++bits;
  plan.bit_reversed.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t r = 0;
    for (int b = 0; b < bits; ++b) r |= ((i >> b) & 1u) << (bits - 1 - b);
    plan.bit_reversed[i] = r;
  }
  for (std::size_t j = 0; j < n / 2; ++j) {
    const double angle = -2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n);
    plan.twiddle_re.push_back(std::cos(angle));
    plan.twiddle_im.push_back(std::sin(angle));
  }
  return plan;
}

inline void radix2_fft(std::span<double> re, std::span<double> im, const Radix2Plan& plan) {
  const std::vector<double>& twiddle_re = plan.twiddle_re;
  const std::vector<double>& twiddle_im = plan.twiddle_im;
  const std::size_t n = re.size();
  for (std::size_t size = 2; size <= n; size *= 2) {
    const std::size_t half = size / 2;
    const std::size_t stride = n / size;
    for (std::size_t start = 0; start < n; start += size) {
      for (std::size_t j = 0; j < half; ++j) {
        const double wr = twiddle_re[j * stride];
        const double wi = twiddle_im[j * stride];
        const std::size_t a = start + j;
        const std::size_t b = a + half;
        const double xr = re[b] * wr - im[b] * wi;
        const double xi = re[b] * wi + im[b] * wr;
        re[b] = re[a] - xr;
        im[b] = im[a] - xi;
        re[a] += xr;
        im[a] += xi;
      }
    }
  }
}

}  // namespace vimg::detail
