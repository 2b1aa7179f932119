// The felt band against the resonator's equation, and the check the validator and the editor use.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "primitives/actuator/felt_band.hpp"
#include "primitives/actuator/primitive_frequencies.hpp"
#include "model_params.hpp"

namespace vimg {
namespace {

using test::lra;


// Where a resonator of quality q is `db` below its peak: |x - 1/x| = sqrt(10^(db/10) - 1) / q.
std::pair<double, double> resonator_edges(double f0, double q, double db) {
  const double d = std::sqrt(std::pow(10.0, db / 10.0) - 1.0) / q;
  const double x = (d + std::sqrt(d * d + 4.0)) / 2.0;
  return {f0 / x, f0 * x};
}

TEST(FeltBand, LraBandIsWhereTheResonatorIsWithinTenDb) {
  for (const double q : {5.0, 10.0, 20.0}) {
    const ActuatorModel model(lra(q), 48000.0);
    const FeltBand band(model);
    const auto [low, high] = resonator_edges(175.0, q, kFeltWithinDb);
    EXPECT_NEAR(band.felt().low_hz, low, 0.005 * low) << q;
    EXPECT_NEAR(band.felt().high_hz, high, 0.005 * high) << q;
    EXPECT_NEAR(model.response_db(band.felt().low_hz), -kFeltWithinDb, 1e-6);
    const auto [comfort_low, comfort_high] = resonator_edges(175.0, q, kComfortWithinDb);
    EXPECT_NEAR(band.comfort().low_hz, comfort_low, 0.005 * comfort_low);
    EXPECT_NEAR(band.comfort().high_hz, comfort_high, 0.005 * comfort_high);
    EXPECT_NEAR(band.peak_hz(), 175.0, 1.0);
  }
}

TEST(FeltBand, A20HzTextureIsWeakOnTheLraAnd175HzIsNot) {
  const ActuatorModel model(lra(10.0), 48000.0);
  const FeltBand band(model);
  const FeltCheck low = band.check(20.0);
  EXPECT_TRUE(low.weak);
  EXPECT_NEAR(low.response_db, model.response_db(20.0), 1e-9);
  EXPECT_FALSE(band.check(175.0).weak);
  // The suggestion is felt comfortably and is the nearest such frequency.
  EXPECT_GE(model.response_db(low.suggested_frequency_hz), -kComfortWithinDb - 1e-6);
  EXPECT_NEAR(low.suggested_frequency_hz, band.comfort().low_hz, 1e-9);
  EXPECT_NEAR(band.check(1000.0).suggested_frequency_hz, band.comfort().high_hz, 1e-9);
  EXPECT_EQ(band.check(180.0).suggested_frequency_hz, 180.0);
  // Every frequency: weak exactly when more than 10 dB down.
  for (double f = 1.0; f < 20000.0; f *= 1.02) EXPECT_EQ(band.check(f).weak, model.response_db(f) < -kFeltWithinDb) << f;
}

TEST(FeltBand, NothingIsWeakOnTheIdealActuator) {
  const ActuatorModel model(ResponseParams{}, 48000.0);
  const FeltBand band(model);
  EXPECT_EQ(band.felt().low_hz, 0.0);
  EXPECT_EQ(band.felt().high_hz, max_design_frequency_hz(48000.0));
  for (double f = 0.5; f < 20000.0; f *= 1.5) EXPECT_FALSE(band.check(f).weak) << f;
}

TEST(FeltBand, ErmBandRunsFromDcToWhereItsLagIsTenDbDown) {
  const ActuatorModel model(test::erm(0.030, 0.050), 48000.0);
  const FeltBand band(model);
  EXPECT_EQ(band.felt().low_hz, 0.0);
  EXPECT_EQ(band.peak_hz(), 0.0);
  const double expected_high = 3.0 / (2.0 * std::numbers::pi * 0.040);  // 2 pi f tau = sqrt(10 - 1)
  EXPECT_NEAR(band.felt().high_hz, expected_high, 0.01 * expected_high);
}

TEST(PrimitiveFrequencies, SurfaceAtFullSpeedLineItsOwnDotTheCarrierThroughGroups) {
  Image image;
  image.interaction = InteractionParams{};
  image.interaction->full_speed_mm_per_s = 120.0;
  Surface surface;
  surface.period_mm = 4.0;
  Line line;
  line.frequency_hz = 60.0;
  Group group;
  group.children.push_back(Element{"l", line, {}, {}, 7});
  group.children.push_back(Element{"d", Dot{}, {}, {}, 8});
  image.children.push_back(Element{"s", surface, {}, {}, 5});
  image.children.push_back(Element{"g", group, {}, {}, 6});
  const auto all = primitive_frequencies(image, 175.0);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].kind, "surface");
  EXPECT_DOUBLE_EQ(all[0].frequency_hz, 30.0);
  EXPECT_EQ(all[0].element->source_line, 5);
  EXPECT_EQ(all[1].kind, "line");
  EXPECT_DOUBLE_EQ(all[1].frequency_hz, 60.0);
  EXPECT_EQ(all[2].kind, "dot");
  EXPECT_DOUBLE_EQ(all[2].frequency_hz, 175.0);
  EXPECT_EQ(all[2].element->id, "d");
}

}  // namespace
}  // namespace vimg
