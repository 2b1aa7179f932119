// The equalizer against its contract: it never boosts, never drives beyond |drive| <= 1, and with
// it the modelled acceleration of the 175 Hz LRA is flat within 3 dB from 120 to 250 Hz.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "primitives/actuator/actuator_chain.hpp"
#include "primitives/actuator/equalizer.hpp"
#include "model_params.hpp"
#include "sine_measure.hpp"

namespace vimg {
namespace {

using test::lra;


TEST(Equalizer, NeverBoosts) {
  for (const double q : {2.0, 10.0, 40.0}) {
    const Equalizer eq(lra(q), 8000.0);
    for (double f = 1.0; f < 4000.0; f *= 1.01) EXPECT_LE(eq.response_db(f), 1e-9) << f;
    EXPECT_NEAR(eq.response_db(175.0), 20.0 * std::log10(kEqualizedQ / q), 1e-6);  // the resonance cut by Qe/Q
  }
}

TEST(Equalizer, ModelTimesEqualizerIsABandPassOfTheEqualizedQ) {
  const ResponseParams p = lra(10.0);
  const ActuatorModel model(p, 48000.0);
  const Equalizer eq(p, 48000.0);
  for (double f = 20.0; f < 1000.0; f *= 1.05) {
    const double x = f / 175.0 - 175.0 / f;
    const double expected = 20.0 * std::log10(kEqualizedQ / p.q) - 10.0 * std::log10(1.0 + kEqualizedQ * kEqualizedQ * x * x);
    EXPECT_NEAR(model.response_db(f) + eq.response_db(f), expected, 0.1) << f;
  }
}

TEST(Equalizer, TheEqualizedLraIsFlatWithinThreeDbFrom120To250Hz) {
  const double rate = 8000.0;
  double lowest = 1e9;
  double highest = -1e9;
  for (double f = 120.0; f <= 250.0; f += 5.0) {
    ActuatorChain chain(lra(10.0), rate, OutputSignal::acceleration, true);
    const double db = test::measured_gain_db([&](double x) { return chain.process(static_cast<float>(x)); }, f, rate);
    lowest = std::min(lowest, db);
    highest = std::max(highest, db);
  }
  EXPECT_LE(highest - lowest, 6.0);  // +-3 dB around the middle
  ActuatorChain at120(lra(10.0), rate, OutputSignal::acceleration, true);
  ActuatorChain at175(lra(10.0), rate, OutputSignal::acceleration, true);
  const double db120 = test::measured_gain_db([&](double x) { return at120.process(static_cast<float>(x)); }, 120.0, rate);
  const double db175 = test::measured_gain_db([&](double x) { return at175.process(static_cast<float>(x)); }, 175.0, rate);
  EXPECT_LE(std::fabs(db120 - db175), 3.0);
}

TEST(Equalizer, TheEqualizedDriveStaysWithinTheDriveLimit) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  ActuatorChain chain(lra(10.0), 8000.0, OutputSignal::drive, true);
  double peak = 0.0;
  for (int n = 0; n < 200000; ++n) {
    // Full-scale square waves and noise: the hardest inputs for an IIR's overshoot.
    const double x = n < 100000 ? ((n / 23) % 2 == 0 ? 1.0 : -1.0) : value(random);
    peak = std::max(peak, std::fabs(static_cast<double>(chain.process(static_cast<float>(x)))));
  }
  EXPECT_LE(peak, 1.0);
}

TEST(Equalizer, IsTheIdentityWhereThereIsNothingToFlatten) {
  EXPECT_TRUE(Equalizer(test::voice_coil(), 8000.0).is_identity());
  EXPECT_TRUE(Equalizer(test::erm(0.030, 0.045), 8000.0).is_identity());
  EXPECT_TRUE(Equalizer(lra(kEqualizedQ), 8000.0).is_identity());
  // Without --equalize the drive goes through untouched.
  ActuatorChain drive_only(lra(10.0), 8000.0, OutputSignal::drive, false);
  EXPECT_TRUE(drive_only.is_identity());
}

}  // namespace
}  // namespace vimg
