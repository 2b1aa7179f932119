// The response model against its equations: the filter's measured gain is response_db(), the
// resonator is the second-order band-pass of its Q, the ideal actuator is the identity, the ERM's
// speed lags with its two time constants.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "primitives/actuator/actuator_chain.hpp"
#include "primitives/actuator/actuator_model.hpp"
#include "model_params.hpp"
#include "sine_measure.hpp"

namespace vimg {
namespace {

using test::erm;
using test::lra;
using test::voice_coil;


std::vector<double> log_frequencies(double low_hz, double high_hz, int count) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(low_hz * std::pow(high_hz / low_hz, i / (count - 1.0)));
  return out;
}

TEST(ActuatorModel, TheFiltersMeasuredGainIsResponseDbFrom20To1000Hz) {
  for (const double rate : {8000.0, 48000.0}) {
    for (const ResponseParams& params : {lra(), lra(20.0), voice_coil()}) {
      for (const double f : log_frequencies(20.0, 1000.0, 23)) {
        ActuatorModel model(params, rate);
        const double measured = test::measured_gain_db([&](double x) { return model.process(x); }, f, rate);
        EXPECT_NEAR(measured, model.response_db(f), 0.5) << "rate " << rate << " f " << f << " q " << params.q;
      }
    }
  }
}

TEST(ActuatorModel, TheLraIsTheSecondOrderResonatorOfItsQ) {
  // |H| = 1 / sqrt(1 + Q^2 (f/f0 - f0/f)^2); the bilinear warping stays small below 1 kHz at 48 kHz.
  for (const double q : {5.0, 10.0, 20.0}) {
    const ActuatorModel model(lra(q), 48000.0);
    for (const double f : log_frequencies(20.0, 1000.0, 31)) {
      const double x = f / 175.0 - 175.0 / f;
      const double expected = -10.0 * std::log10(1.0 + q * q * x * x);
      EXPECT_NEAR(model.response_db(f), expected, 0.3) << "f " << f << " q " << q;
    }
    EXPECT_NEAR(model.response_db(175.0), 0.0, 1e-9);  // prewarped: the peak is exactly at resonance
  }
}

TEST(ActuatorModel, PeakGainIsZeroDb) {
  for (const double rate : {2000.0, 8000.0, 48000.0}) {
    for (const ResponseParams& params : {lra(), voice_coil()}) {
      const ActuatorModel model(params, rate);
      double peak = -1e9;
      for (const double f : log_frequencies(1.0, 0.499 * rate, 20000)) peak = std::max(peak, model.response_db(f));
      EXPECT_LE(peak, 1e-6) << "rate " << rate;
      EXPECT_GT(peak, -0.01) << "rate " << rate;
    }
  }
  // Corners an octave apart lose gain in the middle; the model scales it back.
  const ActuatorModel model(voice_coil(200.0, 400.0), 8000.0);
  double peak = -1e9;
  for (const double f : log_frequencies(100.0, 800.0, 20000)) peak = std::max(peak, model.response_db(f));
  EXPECT_NEAR(peak, 0.0, 1e-4);
}

TEST(ActuatorModel, VoiceCoilIsFlatInsideItsBandAndThreeDbDownAtTheCorners) {
  const ActuatorModel model(voice_coil(), 48000.0);
  for (const double f : log_frequencies(100.0, 250.0, 11)) EXPECT_NEAR(model.response_db(f), 0.0, 0.5) << f;
  EXPECT_NEAR(model.response_db(50.0), -3.0, 0.3);
  EXPECT_NEAR(model.response_db(500.0), -3.0, 0.3);
}

TEST(ActuatorModel, TheIdealActuatorIsTheIdentityBitForBit) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  ResponseParams ideal;
  ideal.model = ResponseModel::ideal;
  ActuatorModel model(ideal, 8000.0);
  ActuatorChain acceleration(ideal, 8000.0, OutputSignal::acceleration, true);
  EXPECT_TRUE(acceleration.is_identity());
  for (int i = 0; i < 100000; ++i) {
    const float x = i % 1000 == 0 ? 1e-40f : value(random);  // subnormals too
    const float via_model = static_cast<float>(model.process(x));
    const float via_chain = acceleration.process(x);
    ASSERT_EQ(std::memcmp(&via_model, &x, sizeof x), 0) << i;
    ASSERT_EQ(std::memcmp(&via_chain, &x, sizeof x), 0) << i;
  }
  EXPECT_EQ(model.response_db(20.0), 0.0);
  EXPECT_EQ(model.response_db(3999.0), 0.0);
}

// The time at which a series first crosses `level` (linear interpolation between samples); the
// value at index n is the state after n + 1 samples, at time (n + 1) / rate.
double crossing_time_s(const std::vector<double>& series, double level, bool rising, double rate_hz) {
  for (std::size_t n = 1; n < series.size(); ++n) {
    const bool crossed = rising ? (series[n - 1] < level && series[n] >= level) : (series[n - 1] > level && series[n] <= level);
    if (crossed) return (static_cast<double>(n) + (level - series[n - 1]) / (series[n] - series[n - 1])) / rate_hz;
  }
  return -1.0;
}

TEST(ActuatorModel, ErmSpeedLagsAStepWithItsSpinUpAndSpinDownTimeConstants) {
  const ResponseParams params = erm(0.030, 0.045);
  const double rate = 8000.0;
  ActuatorModel model(params, rate);
  std::vector<double> up, down;
  for (int n = 0; n < 4000; ++n) {
    model.process(1.0);
    up.push_back(model.erm_speed());
  }
  for (int n = 0; n < 4000; ++n) {
    model.process(0.0);
    down.push_back(model.erm_speed());
  }
  // A first-order lag reaches 1 - 1/e of a step after one time constant, 1 - 1/e^3 after three
  // (a quarter sample: the interpolation between samples of an exponential).
  const double tolerance_s = 0.25 / rate;
  EXPECT_NEAR(crossing_time_s(up, 1.0 - std::exp(-1.0), true, rate), params.spin_up_s, tolerance_s);
  EXPECT_NEAR(crossing_time_s(down, std::exp(-1.0), false, rate), params.spin_down_s, tolerance_s);
  EXPECT_NEAR(crossing_time_s(up, 1.0 - std::exp(-3.0), true, rate), 3.0 * params.spin_up_s, tolerance_s);
}

TEST(ActuatorModel, ErmVibratesAtItsRatedFrequencyWithAmplitudeTheSquareOfItsSpeed) {
  const double rate = 8000.0;
  for (const double drive : {1.0, 0.5}) {
    ActuatorModel model(erm(0.030, 0.045, 200.0), rate);
    for (int n = 0; n < 8000; ++n) model.process(drive);  // 1 s: settled
    int rises = 0;
    double previous = model.process(drive);
    double peak = 0.0;
    for (int n = 0; n < 8000; ++n) {
      const double a = model.process(drive);
      if (previous < 0.0 && a >= 0.0) ++rises;
      peak = std::max(peak, std::fabs(a));
      previous = a;
    }
    EXPECT_NEAR(rises, 200.0 * drive, 1.0) << drive;  // frequency follows the speed
    EXPECT_NEAR(peak, drive * drive, 0.01) << drive;  // acceleration ~ speed^2
  }
}

TEST(ActuatorModel, ErmResponseIsTheFirstOrderLagOfTheMeanTimeConstant) {
  const ActuatorModel model(erm(0.030, 0.050), 48000.0);
  const double tau = 0.040;
  for (const double f : {0.5, 2.0, 4.0, 10.0, 30.0}) {
    const double wt = 2.0 * std::numbers::pi * f * tau;
    EXPECT_NEAR(model.response_db(f), -10.0 * std::log10(1.0 + wt * wt), 0.05) << f;
  }
}

}  // namespace
}  // namespace vimg
