#pragma once
// The power spectrum of one frame of kPowerSpectrumFrameSamples samples under a periodic Hann
// window, one-sided and scaled so that a steady sine of peak amplitude A sums to A^2 over its bins:
//   P_k = |sum_n w_n x_n exp(-2 pi i k n / N)|^2 * 32 / (3 N^2),  k = 0 .. N/2,
// (3 N / 8: the sum of the squared window). Bin k stands for k * fs / N.
//
// Threads: pure; the tables are built once, on first use.
#include <cstddef>
#include <span>

namespace vimg::detail {

inline constexpr std::size_t kPowerSpectrumFrameSamples = 4096;
inline constexpr std::size_t kPowerSpectrumBins = kPowerSpectrumFrameSamples / 2 + 1;

// frame: N samples (not yet windowed); power: N/2 + 1 values.
void hann_power_spectrum(std::span<const double, kPowerSpectrumFrameSamples> frame,
                         std::span<double, kPowerSpectrumBins> power);

}  // namespace vimg::detail
