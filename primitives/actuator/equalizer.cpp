#include "primitives/actuator/equalizer.hpp"

#include <algorithm>
#include <numbers>

#include "primitives/actuator/actuator_model.hpp"

namespace vimg {

Equalizer::Equalizer(const ResponseParams& params, double sample_rate_hz) : sample_rate_hz_(sample_rate_hz) {
  if (params.model != ResponseModel::lra || params.q <= kEqualizedQ) return;
  // The same resonance the model is designed at (placed below Nyquist the same way).
  const double f0 = std::min(params.resonance_hz, max_design_frequency_hz(sample_rate_hz));
  const double w0 = 2.0 * std::numbers::pi * f0;
  const AnalogBiquad inverse{1.0 / (w0 * w0), 1.0 / (params.q * w0), 1.0,
                             1.0 / (w0 * w0), 1.0 / (kEqualizedQ * w0), 1.0};
  stage_ = Biquad(bilinear(inverse, sample_rate_hz, f0));
  identity_ = false;
}

double Equalizer::response_db(double frequency_hz) const {
  return identity_ ? 0.0 : stage_.coefficients().gain_db(frequency_hz, sample_rate_hz_);
}

}  // namespace vimg
