#include "primitives/perception/power_spectrum.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "primitives/perception/radix2_fft.hpp"

namespace vimg::detail {

namespace {

constexpr std::size_t kN = kPowerSpectrumFrameSamples;
constexpr int kLog2N = 12;
static_assert(std::size_t{1} << kLog2N == kN);

struct Tables {
  std::vector<double> window = std::vector<double>(kN);
  std::vector<double> twiddle_re = std::vector<double>(kN / 2);  // exp(-2 pi i j / N)
  std::vector<double> twiddle_im = std::vector<double>(kN / 2);
  std::vector<std::size_t> bit_reversed = std::vector<std::size_t>(kN);
};

Tables make_tables() {
  Tables t;
  const double n = static_cast<double>(kN);
  for (std::size_t i = 0; i < kN; ++i) {
    t.window[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / n);
    std::size_t r = 0;
    for (int b = 0; b < kLog2N; ++b) r |= ((i >> b) & 1u) << (kLog2N - 1 - b);
    t.bit_reversed[i] = r;
  }
  for (std::size_t j = 0; j < kN / 2; ++j) {
    const double angle = -2.0 * std::numbers::pi * static_cast<double>(j) / n;
    t.twiddle_re[j] = std::cos(angle);
    t.twiddle_im[j] = std::sin(angle);
  }
  return t;
}

const Tables& tables() {
  static const Tables t = make_tables();
  return t;
}

}  // namespace

void hann_power_spectrum(std::span<const double, kPowerSpectrumFrameSamples> frame,
                         std::span<double, kPowerSpectrumBins> power) {
  const Tables& t = tables();
  std::array<double, kN> re{};
  std::array<double, kN> im{};
  for (std::size_t i = 0; i < kN; ++i) re[t.bit_reversed[i]] = frame[i] * t.window[i];
  radix2_fft(re, im, t.twiddle_re, t.twiddle_im);
  const double n = static_cast<double>(kN);
  const double scale = 32.0 / (3.0 * n * n);
  for (std::size_t k = 0; k < kPowerSpectrumBins; ++k) {
    // One-sided: bins other than DC and Nyquist carry their mirror's half as well.
    const double two_sided = (k == 0 || k == kN / 2) ? 0.5 : 1.0;
    power[k] = (re[k] * re[k] + im[k] * im[k]) * scale * two_sided;
  }
}

}  // namespace vimg::detail
