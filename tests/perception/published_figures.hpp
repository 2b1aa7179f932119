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
  PublishedRange r{1e300, -1e300};
  for (const auto& row : read_csv_rows(std::string(VIMG_TEST_DATA_DIR) + "/psychophysics/published_figures.csv")) {
    if (row.at("quantity") != quantity) continue;
    if (!row_holds(row, "frequency_low_hz", "frequency_high_hz", frequency_hz)) continue;
    if (!std::isnan(sensation_level_db) && !row_holds(row, "sensation_level_low_db", "sensation_level_high_db", sensation_level_db)) continue;
    r.low = std::min(r.low, std::stod(row.at("low")));
    r.high = std::max(r.high, std::stod(row.at("high")));
  }
  return r;
}

}  // namespace vimg::test
