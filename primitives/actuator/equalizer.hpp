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
// moment: full-scale square waves do); clamped_samples() counts the samples it clamped.
//
// Threads: a value type; process() never allocates, locks or throws (one thread per instance).
#include <cstdint>

#include "primitives/actuator/biquad.hpp"
#include "primitives/actuator/response_params.hpp"

namespace vimg {

inline constexpr double kEqualizedQ = 1.0;

class Equalizer {
 public:
  Equalizer(const ResponseParams& params, double sample_rate_hz);

  // The filter alone: what process() clamps (tests bound it).
  double filter(double drive) noexcept { return identity_ ? drive : stage_.process(drive); }
  double process(double drive) noexcept {
    const double y = filter(drive);
    if (y > 1.0 || y < -1.0) {
      ++clamped_samples_;
      return y > 1.0 ? 1.0 : -1.0;
    }
    return y;
  }
  void reset() noexcept {
    stage_.reset();
    clamped_samples_ = 0;
  }
  // Samples that process() clamped since construction or reset().
  std::uint64_t clamped_samples() const noexcept { return clamped_samples_; }
  // 20 log10 |E| at frequency_hz; at most 0 dB.
  double response_db(double frequency_hz) const;
  bool is_identity() const { return identity_; }

 private:
  double sample_rate_hz_;
  Biquad stage_;
  bool identity_ = true;
  std::uint64_t clamped_samples_ = 0;
};

}  // namespace vimg
