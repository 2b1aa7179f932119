#include "primitives/perception/power_spectrum.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "primitives/perception/hann_window.hpp"
#include "primitives/perception/radix2_fft.hpp"

namespace vimg::detail {

namespace {

constexpr std::size_t kN = kPowerSpectrumFrameSamples;

struct Tables {
  std::vector<double> window = std::vector<double>(kN);
  Radix2Plan fft = radix2_plan(kN);
};

Tables make_tables() {
  Tables t;
  for (std::size_t i = 0; i < kN; ++i) t.window[i] = hann_sample(i, kN, 0.0);
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
  for (std::size_t i = 0; i < kN; ++i) re[t.fft.bit_reversed[i]] = frame[i] * t.window[i];
  radix2_fft(re, im, t.fft);
  const double n = static_cast<double>(kN);
  const double scale = 32.0 / (3.0 * n * n);
  for (std::size_t k = 0; k < kPowerSpectrumBins; ++k) {
    // One-sided: bins other than DC and Nyquist carry their mirror's half as well.
    const double two_sided = (k == 0 || k == kN / 2) ? 0.5 : 1.0;
    power[k] = (re[k] * re[k] + im[k] * im[k]) * scale * two_sided;
  }
}

}  // namespace vimg::detail
