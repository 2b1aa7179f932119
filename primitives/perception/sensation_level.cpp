#include "primitives/perception/sensation_level.hpp"

#include <cmath>

#include "primitives/perception/vibrotactile_threshold.hpp"

namespace vimg {

double threshold_peak_displacement_m(double frequency_hz, const LevelCalibration& calibration) {
  const double above_best_db = vibrotactile_threshold_db(frequency_hz) - kThresholdAtBestFrequencyDb;
  return calibration.threshold_at_250hz_peak_displacement_m * std::pow(10.0, above_best_db / 20.0);
}

}  // namespace vimg
