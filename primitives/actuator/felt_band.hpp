#pragma once
// Will a frequency be felt on an actuator? The one answer used by `vimg validate --actuator`,
// `vimg info --actuator` and the editor (docs/actuators.md, "Felt band").
//   felt band:     the frequencies where the modelled response is within kFeltWithinDb (10 dB) of
//                  its peak; outside it a frequency is weak.
//   suggestion:    the nearest frequency where the response is within kComfortWithinDb (6 dB) of
//                  the peak (the frequency itself when it is there already).
// Found from ActuatorModel::response_db() on a log grid from kFeltScanLowHz to the model's highest
// design frequency, edges refined by bisection. A band reaching the bottom of the grid reports
// low_hz = 0 (the response holds down to DC, e.g. an ERM's envelope).
//
// Threads: construction scans (not real-time); check() is a pure function of its input.
#include "primitives/actuator/actuator_model.hpp"

namespace vimg {

inline constexpr double kFeltWithinDb = 10.0;
inline constexpr double kComfortWithinDb = 6.0;
inline constexpr double kFeltScanLowHz = 0.5;

struct FeltCheck {
  double frequency_hz = 0.0;
  double response_db = 0.0;            // re the peak
  bool weak = false;                   // more than kFeltWithinDb below the peak
  double suggested_frequency_hz = 0.0; // inside the comfort band, nearest to frequency_hz
};

struct FrequencyBand {
  double low_hz = 0.0;
  double high_hz = 0.0;
};

class FeltBand {
 public:
  explicit FeltBand(const ActuatorModel& model);

  FeltCheck check(double frequency_hz) const;
  const FrequencyBand& felt() const { return felt_; }       // within 10 dB
  const FrequencyBand& comfort() const { return comfort_; } // within 6 dB
  double peak_hz() const { return peak_hz_; }
  double peak_db() const { return peak_db_; }

 private:
  FrequencyBand band_within(double within_db) const;

  const ActuatorModel& model_;
  double peak_hz_ = 0.0;
  int peak_index_ = 0;
  double peak_db_ = 0.0;
  FrequencyBand felt_;
  FrequencyBand comfort_;
};

}  // namespace vimg
