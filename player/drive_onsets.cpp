#include "player/drive_onsets.hpp"

#include <cmath>
#include <limits>

namespace vimg {

std::vector<double> drive_onsets_s(std::span<const float> drive, double rate_hz, double start_time_s, double threshold,
                                   double quiet_s) {
  std::vector<double> onsets;
  const auto quiet_samples = static_cast<std::size_t>(std::ceil(quiet_s * rate_hz));
  std::size_t quiet_run = quiet_samples;  // the start counts as quiet
  for (std::size_t i = 0; i < drive.size(); ++i) {
    if (std::abs(drive[i]) > threshold) {
      if (quiet_run >= quiet_samples) onsets.push_back(start_time_s + static_cast<double>(i) / rate_hz);
      quiet_run = 0;
    } else {
      ++quiet_run;
    }
  }
  return onsets;
}

double mean_onset_error_mm(const std::vector<double>& exact_onsets_s, const std::vector<double>& felt_onsets_s,
                           double speed_mm_per_s) {
  if (exact_onsets_s.empty() || felt_onsets_s.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double t : exact_onsets_s) {
    double nearest = std::numeric_limits<double>::infinity();
    for (double u : felt_onsets_s) nearest = std::min(nearest, std::abs(u - t));
    sum += nearest * speed_mm_per_s;
  }
  return sum / static_cast<double>(exact_onsets_s.size());
}

}  // namespace vimg
