#pragma once
// The drive equalizer (`vimg render --equalize`, docs/actuators.md): shapes the drive so that the
// modelled acceleration follows the designed intensity across the actuator's band, without ever
// driving harder than the drive limit |drive| <= 1.
//   lra: the inverse of the resonator, clipped to a band: E(s) = D_Q(s) / D_Qe(s), where D_Q is the
//        resonator's denominator s^2/w0^2 + s/(Q w0) + 1 and Qe = kEqualizedQ. E is 0 dB far from
//        resonance and (Qe / Q) at it: it attenuates the resonance and never boosts. Model times
//        equalizer is (Qe / Q) times a band-pass of quality Qe: within 3 dB from 0.62 to 1.62 times
//        the resonance (108-283 Hz for 175 Hz).
//   ideal, voice_coil: identity (the band is already flat).
//   erm: identity: a linear filter on the drive cannot reshape a motor's speed lag.
// The output is clamped to [-1, 1] (a filter whose gain is at most 0 dB can still overshoot for a
// moment).
//
// Threads: a value type; process() never allocates, locks or throws (one thread per instance).
#include "primitives/actuator/biquad.hpp"
#include "primitives/actuator/response_params.hpp"

namespace vimg {

inline constexpr double kEqualizedQ = 1.0;

class Equalizer {
 public:
  Equalizer(const ResponseParams& params, double sample_rate_hz);

  double process(double drive) noexcept {
    if (identity_) return drive;
    const double y = stage_.process(drive);
    return y > 1.0 ? 1.0 : (y < -1.0 ? -1.0 : y);
  }
  void reset() noexcept { stage_.reset(); }
  // 20 log10 |E| at frequency_hz; at most 0 dB.
  double response_db(double frequency_hz) const;
  bool is_identity() const { return identity_; }

 private:
  double sample_rate_hz_;
  Biquad stage_;
  bool identity_ = true;
};

}  // namespace vimg
