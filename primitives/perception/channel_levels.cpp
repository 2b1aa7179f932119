#include "primitives/perception/channel_levels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "primitives/perception/discrimination_cues.hpp"
#include "primitives/perception/hann_window.hpp"
#include "primitives/perception/perception_rate.hpp"
#include "primitives/perception/radix2_fft.hpp"
#include "primitives/perception/stsim.hpp"

namespace vimg::detail {

namespace {

constexpr std::size_t kM = 2 * kChannelFilterTaps;      // FFT size of the overlap-save blocks
constexpr std::size_t kHalfTaps = kChannelFilterTaps / 2;  // the filter is zero for |n| >= this
constexpr std::size_t kValid = kM - kChannelFilterTaps;   // outputs per block
constexpr std::size_t kStepSamples = kEnvelopeStepSamples;  // 1 ms
constexpr double kStepMs = 1000.0 * static_cast<double>(kStepSamples) / kPerceptionRateHz;
static_assert(kValid % kStepSamples == 0 && kHalfTaps % kStepSamples == 0);

const Radix2Plan& plan() {
  static const Radix2Plan p = radix2_plan(kM);
  return p;
}

// In-place forward FFT of natural-order data.
void fft(std::vector<double>& re, std::vector<double>& im) {
  const Radix2Plan& p = plan();
  for (std::size_t i = 0; i < kM; ++i) {
    const std::size_t r = p.bit_reversed[i];
    if (i < r) {
      std::swap(re[i], re[r]);
      std::swap(im[i], im[r]);
    }
  }
  radix2_fft(re, im, p);
}

// The inverse, unscaled (times kM): conj(FFT(conj(X))).
void inverse_fft(std::vector<double>& re, std::vector<double>& im) {
  for (double& v : im) v = -v;
  fft(re, im);
  for (double& v : im) v = -v;
}

// The two channels' zero-phase filters as their (real, even) frequency responses on kM bins:
// pacinian in `re`, non-Pacinian in `im`. Sampled from the sensitivity, to the impulse response,
// cut to kChannelFilterTaps under a Hann window, back to the frequency response.
struct ChannelFilters {
  std::vector<double> pacinian = std::vector<double>(kM, 0.0);
  std::vector<double> non_pacinian = std::vector<double>(kM, 0.0);
};

ChannelFilters design(const LevelCalibration& calibration) {
  ChannelFilters h;
  std::vector<double>& re = h.pacinian;
  std::vector<double>& im = h.non_pacinian;
  for (std::size_t k = 1; k < kM / 2; ++k) {
    const double f = static_cast<double>(k) * kPerceptionRateHz / static_cast<double>(kM);
    if (f < kLowestFeltHz) continue;
    const double omega = 2.0 * std::numbers::pi * f;
    const double displacement_m = calibration.full_scale_peak_acceleration_mps2 / (omega * omega);
    re[k] = re[kM - k] = displacement_m / threshold_peak_displacement_m(f, calibration);
    im[k] = im[kM - k] = displacement_m / kNonPacinianThresholdPeakDisplacementM;
  }
  inverse_fft(re, im);
  for (std::size_t n = 0; n < kM; ++n) {
    const std::size_t d = std::min(n, kM - n);
    const double w = hann(static_cast<double>(d) / static_cast<double>(kHalfTaps));
    re[n] *= w / static_cast<double>(kM);
    im[n] *= w / static_cast<double>(kM);
  }
  fft(re, im);
  return h;
}

double to_db(double mean_excitation) { return mean_excitation > 0.0 ? 10.0 * std::log10(mean_excitation) : kSilentChannelDb; }

// The largest sum of `width` consecutive values (fewer when there are fewer), values >= 0.
double largest_window_sum(const std::vector<double>& values, std::size_t width) {
  double sum = 0.0;
  for (std::size_t i = 0; i < std::min(width, values.size()); ++i) sum += values[i];
  double best = sum;
  // Re-summed exactly every so often, so that rounding does not accumulate over long signals.
  for (std::size_t i = width; i < values.size(); ++i) {
    sum += values[i] - values[i - width];
    if (i % 4096 == 0) {
      sum = 0.0;
      for (std::size_t k = i + 1 - width; k <= i; ++k) sum += values[k];
    }
    best = std::max(best, sum);
  }
  return best;
}

// The sums of `width` consecutive values ending at each index (zeros before the start).
std::vector<double> box_sums(const std::vector<double>& values, std::size_t width) {
  std::vector<double> out(values.size() + width - 1, 0.0);
  double sum = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i < values.size()) sum += values[i];
    if (i >= width) sum -= values[i - width];
    if (i % 4096 == 0) {
      sum = 0.0;
      for (std::size_t k = i >= width - 1 ? i + 1 - width : 0; k <= i && k < values.size(); ++k) sum += values[k];
    }
    out[i] = std::max(0.0, sum);
  }
  return out;
}

}  // namespace

ChannelLevels channel_levels(std::span<const double> signal_8khz, const LevelCalibration& calibration, double moment_ms) {
  const std::size_t size = signal_8khz.size();
  ChannelLevels levels{kSilentChannelDb, kSilentChannelDb, kSilentChannelDb};
  if (size == 0) return levels;
  const ChannelFilters h = design(calibration);

  // Outputs from kHalfTaps before the signal to kHalfTaps after it (the filters' ringing), summed
  // per 1 ms step: sum of 2 y^2.
  const std::size_t outputs = size + 2 * kHalfTaps;
  const std::size_t steps = (outputs + kStepSamples - 1) / kStepSamples;
  std::vector<double> pacinian(steps, 0.0), non_pacinian(steps, 0.0);
  std::vector<double> re(kM), im(kM);
  for (std::size_t first = 0; first < outputs; first += kValid) {
    // Block input: signal samples [first - 2 kHalfTaps, first - 2 kHalfTaps + kM).
    bool any = false;
    for (std::size_t m = 0; m < kM; ++m) {
      const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(first + m) - static_cast<std::ptrdiff_t>(2 * kHalfTaps);
      re[m] = n >= 0 && static_cast<std::size_t>(n) < size ? signal_8khz[static_cast<std::size_t>(n)] : 0.0;
      im[m] = 0.0;
      any = any || re[m] != 0.0;
    }
    if (!any) continue;
    fft(re, im);
    for (std::size_t k = 0; k < kM; ++k) {
      const double a = re[k], b = im[k];
      re[k] = a * h.pacinian[k] - b * h.non_pacinian[k];
      im[k] = b * h.pacinian[k] + a * h.non_pacinian[k];
    }
    inverse_fft(re, im);
    const double scale = 1.0 / static_cast<double>(kM);
    for (std::size_t m = kHalfTaps; m < kHalfTaps + kValid && first + m - kHalfTaps < outputs; ++m) {
      const std::size_t step = (first + m - kHalfTaps) / kStepSamples;
      const double yp = re[m] * scale, ynp = im[m] * scale;
      pacinian[step] += 2.0 * yp * yp;
      non_pacinian[step] += 2.0 * ynp * ynp;
    }
  }

  const auto summation_steps = static_cast<std::size_t>(std::lround(kPacinianSummationMs / kStepMs));
  levels.pacinian_db = to_db(largest_window_sum(pacinian, summation_steps) / (static_cast<double>(summation_steps * kStepSamples)));
  const auto moment_steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(moment_ms / kStepMs)));
  levels.pacinian_moment_db = to_db(largest_window_sum(pacinian, moment_steps) / (static_cast<double>(moment_steps * kStepSamples)));
  // The triangle: a box of half the width, twice.
  const auto half = static_cast<std::size_t>(std::lround(kNonPacinianWindowMs / 2.0 / kStepMs));
  const std::vector<double> twice = box_sums(box_sums(non_pacinian, half), half);
  const double peak = twice.empty() ? 0.0 : *std::max_element(twice.begin(), twice.end());
  levels.non_pacinian_db = to_db(peak / static_cast<double>(half * half * kStepSamples));
  return levels;
}

}  // namespace vimg::detail
