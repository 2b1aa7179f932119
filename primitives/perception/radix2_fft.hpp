#pragma once
// The iterative radix-2 decimation-in-time FFT shared by the 512-point DCT of ST-SIM
// (block_dct.cpp) and the 4096-point power spectrum of the discrimination model
// (power_spectrum.cpp): in place over N = re.size() points (a power of two) already placed in
// bit-reversed order, with twiddle_re[j] + i twiddle_im[j] = exp(-2 pi i j / N), j < N / 2.
#include <cstddef>
#include <span>

namespace vimg::detail {

inline void radix2_fft(std::span<double> re, std::span<double> im, std::span<const double> twiddle_re,
                       std::span<const double> twiddle_im) {
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
