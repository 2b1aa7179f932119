#pragma once
// The orthonormal DCT-II of one 512-sample block, as scipy.fftpack.dct(x, norm="ortho") defines it:
//   X_0 = sqrt(1/N) sum x_n,  X_k = sqrt(2/N) sum x_n cos(pi k (2n + 1) / (2N)),  N = 512,
// computed in O(N log N) through one complex FFT of N points (Makhoul 1980). Bin k stands for the
// frequency k * fs / (2N).
#include <span>

#include "primitives/perception/stsim.hpp"

namespace vimg::detail {

void orthonormal_dct_512(std::span<const double, kStSimBlockSamples> block,
                         std::span<double, kStSimBlockSamples> coefficients);

}  // namespace vimg::detail
