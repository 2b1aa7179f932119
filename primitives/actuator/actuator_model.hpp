#pragma once
// The actuator response model (docs/actuators.md): turns normalized drive into the modelled
// acceleration, normalized so that the peak gain is 0 dB.
//   ideal       acceleration = drive, sample for sample (bit-identical)
//   lra         second-order resonator (band-pass) at resonance_hz with quality factor q
//   voice_coil  flat band: 2nd-order Butterworth high-pass at low_hz times low-pass at high_hz
//   erm         speed follows |drive| with a first-order lag (spin_up_s rising, spin_down_s
//               falling); acceleration = speed^2 * sin(phase), phase advancing at speed * resonance_hz
// The linear models are biquads from the bilinear transform prewarped at their design frequency;
// response_db() evaluates the same coefficients. A design frequency above 0.45 * sample rate is
// placed at 0.45 * sample rate (the rate cannot represent it).
//
// Threads: a value type. Construction designs the filters (not real-time); process() never
// allocates, locks or throws and may run on a real-time thread (one thread per instance).
#include <array>

#include "primitives/actuator/biquad.hpp"
#include "primitives/actuator/response_params.hpp"

namespace vimg {

class ActuatorModel {
 public:
  ActuatorModel(const ResponseParams& params, double sample_rate_hz);

  // One sample of drive in, one sample of modelled acceleration out.
  double process(double drive) noexcept;
  void reset() noexcept;

  // The steady-state magnitude response at frequency_hz, dB re the peak (so at most 0 dB). For the
  // erm: the response of the speed envelope to a modulation of the drive at frequency_hz (the lag
  // with the mean of the two time constants), since an ERM's own vibration frequency is set by its
  // speed, not by the drive's waveform. At or above half the sample rate: -400 dB.
  double response_db(double frequency_hz) const;

  const ResponseParams& params() const { return params_; }
  double sample_rate_hz() const { return sample_rate_hz_; }
  bool is_identity() const { return params_.model == ResponseModel::ideal; }
  // erm: the normalized motor speed in [0, 1]; 0 for the other models.
  double erm_speed() const { return speed_; }

 private:
  ResponseParams params_;
  double sample_rate_hz_;
  std::array<Biquad, 2> stages_{};
  int stage_count_ = 0;
  // erm state and constants
  double rise_step_ = 0.0;   // 1 - exp(-T / spin_up_s)
  double fall_step_ = 0.0;   // 1 - exp(-T / spin_down_s)
  double phase_step_ = 0.0;  // 2 pi resonance_hz T
  BiquadCoefficients envelope_lag_;  // the one-pole response_db() reports for the erm
  double speed_ = 0.0;
  double phase_ = 0.0;
};

// The highest frequency a filter designed at sample_rate_hz is placed at.
double max_design_frequency_hz(double sample_rate_hz);

}  // namespace vimg
