#pragma once
// What a render writes per sample (`vimg render --signal drive|acceleration [--equalize]`): the
// drive, optionally equalized (equalizer.hpp), and then either that drive or the modelled
// acceleration of the actuator receiving it (actuator_model.hpp). Stages that are the identity
// are skipped, so the ideal actuator gives its input back bit for bit.
//
// Threads: a value type; process() never allocates, locks or throws (one thread per instance).
#include "primitives/actuator/actuator_model.hpp"
#include "primitives/actuator/equalizer.hpp"

namespace vimg {

enum class OutputSignal { drive, acceleration };

class ActuatorChain {
 public:
  ActuatorChain(const ResponseParams& params, double sample_rate_hz, OutputSignal signal, bool equalize)
      : equalizer_(params, sample_rate_hz),
        model_(params, sample_rate_hz),
        equalize_(equalize && !equalizer_.is_identity()),
        model_output_(signal == OutputSignal::acceleration && !model_.is_identity()) {}

  float process(float drive) noexcept {
    if (!equalize_ && !model_output_) return drive;
    double x = drive;
    if (equalize_) x = equalizer_.process(x);
    if (model_output_) x = model_.process(x);
    return static_cast<float>(x);
  }
  void reset() noexcept {
    equalizer_.reset();
    model_.reset();
  }
  // Samples the equalizer clamped to the drive limit since construction or reset().
  std::uint64_t clamped_samples() const noexcept { return equalize_ ? equalizer_.clamped_samples() : 0; }
  // True when process() returns its input unchanged.
  bool is_identity() const { return !equalize_ && !model_output_; }

 private:
  Equalizer equalizer_;
  ActuatorModel model_;
  bool equalize_;
  bool model_output_;
};

}  // namespace vimg
