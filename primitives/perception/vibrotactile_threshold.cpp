#include "primitives/perception/vibrotactile_threshold.hpp"

#include <cmath>

namespace vimg {

namespace {

// The reference's constants (x_scaler, y_scaler, x_offset, y_offset), in its order of operations.
constexpr double kScaleDb = 62.0;
constexpr double kFrequencyScale = 1.0 / 550.0;
constexpr double kOffset = 1.0 - 250.0 * kFrequencyScale;
constexpr double kFloorDb = 77.0;

double raw_threshold_db(double frequency_hz) {
  const double log_offset = std::log10(kOffset);
  const double log_f = std::log10(kFrequencyScale * frequency_hz + kOffset);
  return std::abs(kScaleDb / (log_offset * log_offset) * (log_f * log_f)) - kFloorDb;
}

// Where the curve first reaches 0 dB above 250 Hz: log10(f / 550 + c) = -log10(c) sqrt(77 / 62).
double zero_crossing_hz() {
  const double log_f = -std::log10(kOffset) * std::sqrt(kFloorDb / kScaleDb);
  return (std::pow(10.0, log_f) - kOffset) / kFrequencyScale;
}

std::array<double, kStSimBlockSamples> make_table() {
  std::array<double, kStSimBlockSamples> table{};
  // numpy.linspace(0, 8000, 1024): k * (8000 / 1023).
  const double step = kStSimSampleRateHz / static_cast<double>(2 * kStSimBlockSamples - 1);
  for (std::size_t k = 0; k < table.size(); ++k) table[k] = raw_threshold_db(static_cast<double>(k) * step);
  // From the first positive bin on, that bin's value (numpy.argmax(t > 0) is 0 when none is).
  std::size_t limit = 0;
  while (limit < table.size() && !(table[limit] > 0.0)) ++limit;
  if (limit == table.size()) limit = 0;
  for (std::size_t k = limit + 1; k < table.size(); ++k) table[k] = table[limit];
  return table;
}

}  // namespace

double vibrotactile_threshold_db(double frequency_hz) {
  static const double crossing_hz = zero_crossing_hz();
  if (!(frequency_hz >= 0.0)) frequency_hz = 0.0;
  if (frequency_hz >= crossing_hz) return 0.0;
  return raw_threshold_db(frequency_hz);
}

const std::array<double, kStSimBlockSamples>& stsim_threshold_db_per_bin() {
  static const std::array<double, kStSimBlockSamples> table = make_table();
  return table;
}

}  // namespace vimg
