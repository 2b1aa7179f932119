#include "primitives/actuator/actuator_model.hpp"

#include "primitives/actuator/golden_section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vimg {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Band-pass resonator with 0 dB at w0: H(s) = (s / (Q w0)) / (s^2 / w0^2 + s / (Q w0) + 1).
AnalogBiquad resonator(double frequency_hz, double q) {
  const double w0 = kTwoPi * frequency_hz;
  return {0.0, 1.0 / (q * w0), 0.0, 1.0 / (w0 * w0), 1.0 / (q * w0), 1.0};
}

constexpr double kButterworthQ = 0.70710678118654752;

AnalogBiquad high_pass(double frequency_hz) {
  const double w0 = kTwoPi * frequency_hz;
  return {1.0 / (w0 * w0), 0.0, 0.0, 1.0 / (w0 * w0), 1.0 / (kButterworthQ * w0), 1.0};
}

AnalogBiquad low_pass(double frequency_hz) {
  const double w0 = kTwoPi * frequency_hz;
  return {0.0, 0.0, 1.0, 1.0 / (w0 * w0), 1.0 / (kButterworthQ * w0), 1.0};
}

double product_magnitude(const std::array<Biquad, 2>& stages, int count, double frequency_hz, double rate_hz) {
  double m = 1.0;
  for (int i = 0; i < count; ++i) {
    m *= std::abs(stages[static_cast<std::size_t>(i)].coefficients().response(frequency_hz, rate_hz));
  }
  return m;
}

// The largest |H| between 0.1 Hz and just below Nyquist: a log grid, then golden-section
// refinement around the best grid point.
double peak_magnitude(const std::array<Biquad, 2>& stages, int count, double rate_hz) {
  constexpr int kPoints = 2000;
  const double low = std::log(0.1);
  const double high = std::log(0.4999 * rate_hz);
  const double step = (high - low) / (kPoints - 1);
  int best = 0;
  double best_m = 0.0;
  for (int i = 0; i < kPoints; ++i) {
    const double m = product_magnitude(stages, count, std::exp(low + step * i), rate_hz);
    if (m > best_m) {
      best_m = m;
      best = i;
    }
  }
  const double at = golden_section_argmax(
      [&](double log_f) { return product_magnitude(stages, count, std::exp(log_f), rate_hz); },
      low + step * std::max(0, best - 1), low + step * std::min(kPoints - 1, best + 1));
  return std::max(best_m, product_magnitude(stages, count, std::exp(at), rate_hz));
}

}  // namespace

double max_design_frequency_hz(double sample_rate_hz) { return 0.45 * sample_rate_hz; }

ActuatorModel::ActuatorModel(const ResponseParams& params, double sample_rate_hz)
    : params_(params), sample_rate_hz_(sample_rate_hz) {
  const double top = max_design_frequency_hz(sample_rate_hz);
  const auto place = [top](double hz) { return std::min(hz, top); };
  switch (params.model) {
    case ResponseModel::ideal:
      break;
    case ResponseModel::lra: {
      const double f0 = place(params.resonance_hz);
      // Prewarped at the resonance: the digital peak is at f0 and is exactly 0 dB.
      stages_[0] = Biquad(bilinear(resonator(f0, params.q), sample_rate_hz, f0));
      stage_count_ = 1;
      break;
    }
    case ResponseModel::voice_coil: {
      const double low = place(params.low_hz);
      const double high = place(params.high_hz);
      stages_[0] = Biquad(bilinear(high_pass(low), sample_rate_hz, low));
      stages_[1] = Biquad(bilinear(low_pass(high), sample_rate_hz, high));
      stage_count_ = 2;
      // Corners close together lose gain in the middle: scale the peak back to 0 dB.
      BiquadCoefficients first = stages_[0].coefficients();
      first.scale(1.0 / peak_magnitude(stages_, stage_count_, sample_rate_hz));
      stages_[0] = Biquad(first);
      break;
    }
    case ResponseModel::erm: {
      const double period_s = 1.0 / sample_rate_hz;
      rise_step_ = 1.0 - std::exp(-period_s / params.spin_up_s);
      fall_step_ = 1.0 - std::exp(-period_s / params.spin_down_s);
      phase_step_ = kTwoPi * params.resonance_hz * period_s;
      const double mean_step = 1.0 - std::exp(-period_s / (0.5 * (params.spin_up_s + params.spin_down_s)));
      envelope_lag_.b0 = mean_step;
      envelope_lag_.a1 = -(1.0 - mean_step);
      break;
    }
  }
}

double ActuatorModel::process(double drive) noexcept {
  switch (params_.model) {
    case ResponseModel::ideal:
      return drive;
    case ResponseModel::lra:
      return stages_[0].process(drive);
    case ResponseModel::voice_coil:
      return stages_[1].process(stages_[0].process(drive));
    case ResponseModel::erm: {
      const double target = std::min(1.0, std::fabs(drive));
      speed_ += (target - speed_) * (target > speed_ ? rise_step_ : fall_step_);
      phase_ += phase_step_ * speed_;
      if (phase_ >= kTwoPi) phase_ -= kTwoPi;
      return speed_ * speed_ * std::sin(phase_);
    }
  }
  return drive;
}

void ActuatorModel::reset() noexcept {
  for (Biquad& stage : stages_) stage.reset();
  speed_ = 0.0;
  phase_ = 0.0;
}

double ActuatorModel::response_db(double frequency_hz) const {
  constexpr double kOutOfBandDb = -400.0;
  if (!(frequency_hz >= 0.0) || frequency_hz >= 0.5 * sample_rate_hz_) return kOutOfBandDb;
  switch (params_.model) {
    case ResponseModel::ideal:
      return 0.0;
    case ResponseModel::erm:
      return envelope_lag_.gain_db(frequency_hz, sample_rate_hz_);
    case ResponseModel::lra:
    case ResponseModel::voice_coil: {
      const double m = product_magnitude(stages_, stage_count_, frequency_hz, sample_rate_hz_);
      return m > 0.0 ? std::max(kOutOfBandDb, 20.0 * std::log10(m)) : kOutOfBandDb;
    }
  }
  return 0.0;
}

}  // namespace vimg
