#pragma once
// The published figures of tests/data/psychophysics/published_figures.csv (README.md there), read
// by quantity, frequency and sensation level: the ranges the conformance tests hold the model to.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "fixture_signals.hpp"

namespace vimg::test {

struct PublishedRange {
  double low = 0.0;
  double high = 0.0;
  double middle() const { return std::sqrt(low * high); }  // geometric: every figure is > 0
  bool holds(double x) const { return x >= low && x <= high; }
};

// Does the row's [low, high] column pair hold x? An empty pair holds everything.
inline bool row_holds(const std::map<std::string, std::string>& row, const std::string& low_column,
                      const std::string& high_column, double x) {
  const std::string& low = row.at(low_column);
  const std::string& high = row.at(high_column);
  if (low.empty() && high.empty()) return true;
  return x >= std::stod(low) && x <= std::stod(high);
}

// The union of the published ranges of `quantity` whose frequency range holds frequency_hz and
// whose sensation-level range holds sensation_level_db (NAN: any). low > high when no row applies.
inline PublishedRange published_range(const std::string& quantity, double frequency_hz, double sensation_level_db = NAN) {
  static const auto rows = read_csv_rows(std::string(VIMG_TEST_DATA_DIR) + "/psychophysics/published_figures.csv");
  PublishedRange r{1e300, -1e300};
  for (const auto& row : rows) {
    if (row.at("quantity") != quantity) continue;
    if (!row_holds(row, "frequency_low_hz", "frequency_high_hz", frequency_hz)) continue;
    if (!std::isnan(sensation_level_db) && !row_holds(row, "sensation_level_low_db", "sensation_level_high_db", sensation_level_db)) continue;
    r.low = std::min(r.low, std::stod(row.at("low")));
    r.high = std::max(r.high, std::stod(row.at("high")));
  }
  return r;
}

// The published detection threshold at frequency_hz (10-300 Hz) as peak displacement in m, a band:
//   up to 40 Hz the flat non-Pacinian floor (detection_threshold_peak_displacement_um, 10-40 Hz);
//   from 250 Hz the Pacinian minimum (the same quantity, 200-300 Hz);
//   between, the minimum's band raised below 250 Hz by the published slope
//   (detection_threshold_slope_db_per_octave): its low end by the low slope, its high end by the high.
// Never the model's own threshold.
inline PublishedRange published_threshold_band_m(double frequency_hz) {
  const char* quantity = "detection_threshold_peak_displacement_um";
  PublishedRange um;
  if (frequency_hz <= 40.0 || frequency_hz >= 250.0) {
    um = published_range(quantity, frequency_hz);
  } else {
    const PublishedRange minimum = published_range(quantity, 250.0);
    const PublishedRange slope = published_range("detection_threshold_slope_db_per_octave", frequency_hz);
    const double octaves = std::log2(250.0 / frequency_hz);
    um = {minimum.low * std::pow(10.0, slope.low * octaves / 20.0), minimum.high * std::pow(10.0, slope.high * octaves / 20.0)};
  }
  return {um.low * 1e-6, um.high * 1e-6};
}

// The stimuli's threshold: the middle (geometric) of the published band.
inline double published_threshold_peak_displacement_m(double frequency_hz) {
  return published_threshold_band_m(frequency_hz).middle();
}

}  // namespace vimg::test
