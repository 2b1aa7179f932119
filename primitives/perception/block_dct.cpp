#include "primitives/perception/block_dct.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "primitives/perception/radix2_fft.hpp"

namespace vimg::detail {

namespace {

constexpr std::size_t kN = kStSimBlockSamples;

struct Tables {
  Radix2Plan fft = radix2_plan(kN);
  std::array<double, kN> post_re{};          // 2 scale_k exp(-i pi k / (2N))
  std::array<double, kN> post_im{};
};

Tables make_tables() {
  Tables t;
  const double n = static_cast<double>(kN);
  for (std::size_t k = 0; k < kN; ++k) {
    const double scale = 2.0 * (k == 0 ? std::sqrt(1.0 / (4.0 * n)) : std::sqrt(1.0 / (2.0 * n)));
    const double angle = -std::numbers::pi * static_cast<double>(k) / (2.0 * n);
    t.post_re[k] = scale * std::cos(angle);
    t.post_im[k] = scale * std::sin(angle);
  }
  return t;
}

const Tables& tables() {
  static const Tables t = make_tables();
  return t;
}

}  // namespace

void orthonormal_dct_512(std::span<const double, kStSimBlockSamples> block,
                         std::span<double, kStSimBlockSamples> coefficients) {
  const Tables& t = tables();
  // Makhoul's reordering: even samples forward, odd samples backward, placed bit-reversed.
  std::array<double, kN> re{};
  std::array<double, kN> im{};
  for (std::size_t n = 0; n < kN / 2; ++n) {
    re[t.fft.bit_reversed[n]] = block[2 * n];
    re[t.fft.bit_reversed[kN - 1 - n]] = block[2 * n + 1];
  }
  radix2_fft(re, im, t.fft);
  for (std::size_t k = 0; k < kN; ++k) coefficients[k] = re[k] * t.post_re[k] - im[k] * t.post_im[k];
}

}  // namespace vimg::detail
