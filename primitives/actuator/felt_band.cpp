#include "primitives/actuator/felt_band.hpp"

#include <algorithm>
#include <cmath>

#include "primitives/actuator/golden_section.hpp"

namespace vimg {

namespace {

constexpr int kScanPoints = 1200;

double scan_frequency(double low_hz, double high_hz, int i) {
  return low_hz * std::pow(high_hz / low_hz, static_cast<double>(i) / (kScanPoints - 1));
}

}  // namespace

FeltBand::FeltBand(const ActuatorModel& model) : model_(model) {
  const double top = max_design_frequency_hz(model.sample_rate_hz());
  peak_db_ = -1e300;
  for (int i = 0; i < kScanPoints; ++i) {
    const double f = scan_frequency(kFeltScanLowHz, top, i);
    const double db = model.response_db(f);
    if (db > peak_db_) {
      peak_db_ = db;
      peak_hz_ = f;
      peak_index_ = i;
    }
  }
  // Refine between the grid neighbours; a response held down to the bottom of the grid peaks at DC.
  if (model.response_db(kFeltScanLowHz) >= peak_db_ - 1e-9) {
    peak_hz_ = 0.0;
    peak_db_ = model.response_db(0.0);
  } else {
    const double log_f = golden_section_argmax(
        [&](double x) { return model.response_db(std::exp(x)); },
        std::log(scan_frequency(kFeltScanLowHz, top, std::max(0, peak_index_ - 1))),
        std::log(scan_frequency(kFeltScanLowHz, top, std::min(kScanPoints - 1, peak_index_ + 1))));
    if (model.response_db(std::exp(log_f)) > peak_db_) {
      peak_hz_ = std::exp(log_f);
      peak_db_ = model.response_db(peak_hz_);
    }
  }
  felt_ = band_within(kFeltWithinDb);
  comfort_ = band_within(kComfortWithinDb);
}

FrequencyBand FeltBand::band_within(double within_db) const {
  const double top = max_design_frequency_hz(model_.sample_rate_hz());
  const double floor_db = peak_db_ - within_db;
  const auto inside = [&](double f) { return model_.response_db(f) >= floor_db; };
  // The grid points around the peak, walking out until the response falls below the floor.
  int lo = peak_index_;
  while (lo > 0 && inside(scan_frequency(kFeltScanLowHz, top, lo - 1))) --lo;
  int hi = peak_index_;
  while (hi < kScanPoints - 1 && inside(scan_frequency(kFeltScanLowHz, top, hi + 1))) ++hi;
  // Bisect each edge between the last point inside and the first outside.
  const auto edge = [&](double in_hz, double out_hz) {
    for (int i = 0; i < 50; ++i) {
      const double mid = std::sqrt(in_hz * out_hz);
      (inside(mid) ? in_hz : out_hz) = mid;
    }
    return in_hz;
  };
  FrequencyBand band;
  band.low_hz = lo == 0 ? 0.0 : edge(scan_frequency(kFeltScanLowHz, top, lo), scan_frequency(kFeltScanLowHz, top, lo - 1));
  band.high_hz = hi == kScanPoints - 1 ? top
                                       : edge(scan_frequency(kFeltScanLowHz, top, hi), scan_frequency(kFeltScanLowHz, top, hi + 1));
  return band;
}

FeltCheck FeltBand::check(double frequency_hz) const {
  FeltCheck c;
  c.frequency_hz = frequency_hz;
  c.response_db = model_.response_db(frequency_hz) - peak_db_;
  c.weak = !(c.response_db >= -kFeltWithinDb);
  c.suggested_frequency_hz = frequency_hz;
  if (frequency_hz < comfort_.low_hz || !(frequency_hz >= 0.0)) c.suggested_frequency_hz = comfort_.low_hz;
  if (frequency_hz > comfort_.high_hz) c.suggested_frequency_hz = comfort_.high_hz;
  return c;
}

}  // namespace vimg
