#include "primitives/perception/sensation_level.hpp"

#include <cmath>

#include "primitives/perception/vibrotactile_threshold.hpp"

namespace vimg {

namespace {

// The threshold's shape, dB above its value at its best frequency (250 Hz, where ST-SIM's curve
// has its minimum too).
double pacinian_threshold_re_best_db(double frequency_hz) {
  if (!(frequency_hz >= kLowestModelledThresholdHz)) frequency_hz = kLowestModelledThresholdHz;  // NaN too
  if (frequency_hz <= kThresholdBestFrequencyHz) {
    return kPacinianSlopeBelowBestDbPerOctave * std::log2(kThresholdBestFrequencyHz / frequency_hz);
  }
  return vibrotactile_threshold_db(frequency_hz) - kThresholdAtBestFrequencyDb;
}

}  // namespace

double threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration) {
  return calibration.threshold_at_250hz_peak_displacement_m * std::pow(10.0, pacinian_threshold_re_best_db(frequency_hz) / 20.0);
}

}  // namespace vimg
