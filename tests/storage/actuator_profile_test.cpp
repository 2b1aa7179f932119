#include <gtest/gtest.h>

#include "storage/actuator_profile.hpp"

namespace vimg {
namespace {

const std::string kProfiles = std::string(VIMG_SOURCE_DIR) + "/assets/profiles/";

TEST(ActuatorProfile, ShippedLraProfileLoads) {
  const auto result = load_actuator_profile(kProfiles + "lra-175hz-drv2605l.xml");
  ASSERT_TRUE(result.profile) << (result.errors.empty() ? "" : result.errors.front());
  const ActuatorProfile& profile = *result.profile;
  EXPECT_EQ(profile.type, ActuatorType::lra);
  EXPECT_DOUBLE_EQ(profile.resonance_hz, 175.0);
  EXPECT_DOUBLE_EQ(profile.rated_voltage_V, 1.8);
  EXPECT_DOUBLE_EQ(profile.overdrive_clamp_V, 2.5);
  EXPECT_DOUBLE_EQ(profile.min_pulse_s, 0.020);
  EXPECT_TRUE(profile.braking);
  EXPECT_EQ(profile.driver, DriverChip::drv2605l);
  EXPECT_EQ(profile.bus, "/dev/i2c-1");
  EXPECT_EQ(profile.address, 0x5A);
  ASSERT_TRUE(profile.enable_pin);
  EXPECT_EQ(profile.enable_pin->chip, "gpiochip0");
  EXPECT_EQ(profile.enable_pin->line, 17u);
}

TEST(ActuatorProfile, ShippedAudioAndIdealProfilesLoad) {
  const auto audio = load_actuator_profile(kProfiles + "voice-coil-audio.xml");
  ASSERT_TRUE(audio.profile);
  EXPECT_EQ(audio.profile->type, ActuatorType::voice_coil);
  EXPECT_EQ(audio.profile->driver, DriverChip::audio);
  const auto ideal = load_actuator_profile(kProfiles + "ideal.xml");
  ASSERT_TRUE(ideal.profile);
  EXPECT_EQ(ideal.profile->type, ActuatorType::ideal);
  EXPECT_DOUBLE_EQ(ideal.profile->resonance_hz, 175.0);  // the spec's DOT carrier for the ideal actuator
}

TEST(ActuatorProfile, ErrorsNameFileLineAndProblem) {
  const char* xml =
      "<actuator name=\"x\" type=\"lra\">\n"
      "  <resonance hz=\"abc\"/>\n"
      "  <drive rated_voltage_V=\"2.0\" overdrive_clamp_V=\"1.0\"/>\n"
      "  <driver chip=\"drv2605l\" address=\"0x99\"><pin role=\"enable\" gpio=\"17\"/></driver>\n"
      "  <colour/>\n"
      "</actuator>\n";
  const auto result = parse_actuator_profile(xml, "bad.xml");
  EXPECT_FALSE(result.profile);
  ASSERT_EQ(result.errors.size(), 5u);
  EXPECT_EQ(result.errors[0].rfind("bad.xml:2: error: ", 0), 0u) << result.errors[0];
  EXPECT_NE(result.errors[0].find("hz"), std::string::npos);
  EXPECT_EQ(result.errors[1].rfind("bad.xml:3: error: ", 0), 0u) << result.errors[1];
  EXPECT_EQ(result.errors[2].rfind("bad.xml:4: error: ", 0), 0u) << result.errors[2];
  EXPECT_NE(result.errors[2].find("address"), std::string::npos);
  EXPECT_EQ(result.errors[3].rfind("bad.xml:4: error: ", 0), 0u) << result.errors[3];
  EXPECT_EQ(result.errors[4].rfind("bad.xml:5: error: ", 0), 0u) << result.errors[4];
}

TEST(ActuatorProfile, MalformedXmlAndMissingFileAreErrorsNotCrashes) {
  const auto broken = parse_actuator_profile("<actuator name=\"x\"\n type=", "broken.xml");
  ASSERT_EQ(broken.errors.size(), 1u);
  EXPECT_EQ(broken.errors[0].rfind("broken.xml:", 0), 0u);
  const auto missing = load_actuator_profile("/nonexistent/profile.xml");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_NE(missing.errors[0].find("/nonexistent/profile.xml"), std::string::npos);
  const auto wrong_root = parse_actuator_profile("<vibroimage/>", "root.xml");
  ASSERT_EQ(wrong_root.errors.size(), 1u);
  EXPECT_NE(wrong_root.errors[0].find("<actuator>"), std::string::npos);
}

TEST(ActuatorProfile, Drv2605lNeedsARatedVoltage) {
  const auto result = parse_actuator_profile(
      "<actuator name=\"x\" type=\"lra\">\n<driver chip=\"drv2605l\"/>\n</actuator>", "nov.xml");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_NE(result.errors[0].find("rated_voltage_V"), std::string::npos);
}

TEST(ActuatorProfile, ShippedProfilesDescribeTheirResponse) {
  const auto lra = load_actuator_profile(kProfiles + "lra-175hz-drv2605l.xml");
  ASSERT_TRUE(lra.profile);
  EXPECT_EQ(lra.profile->response.model, ResponseModel::lra);
  EXPECT_DOUBLE_EQ(lra.profile->response.resonance_hz, 175.0);
  EXPECT_DOUBLE_EQ(lra.profile->response.q, 10.0);
  const auto erm = load_actuator_profile(kProfiles + "erm-10mm.xml");
  ASSERT_TRUE(erm.profile) << (erm.errors.empty() ? "" : erm.errors.front());
  EXPECT_EQ(erm.profile->type, ActuatorType::erm);
  EXPECT_EQ(erm.profile->response.model, ResponseModel::erm);
  EXPECT_DOUBLE_EQ(erm.profile->response.spin_up_s, 0.030);
  EXPECT_DOUBLE_EQ(erm.profile->response.spin_down_s, 0.045);
  EXPECT_DOUBLE_EQ(erm.profile->response.resonance_hz, 200.0);
  const auto coil = load_actuator_profile(kProfiles + "voice-coil-audio.xml");
  ASSERT_TRUE(coil.profile);
  EXPECT_EQ(coil.profile->response.model, ResponseModel::voice_coil);
  EXPECT_DOUBLE_EQ(coil.profile->response.low_hz, 50.0);
  EXPECT_DOUBLE_EQ(coil.profile->response.high_hz, 500.0);
  const auto ideal = load_actuator_profile(kProfiles + "ideal.xml");
  ASSERT_TRUE(ideal.profile);
  EXPECT_EQ(ideal.profile->response.model, ResponseModel::ideal);
}

TEST(ActuatorProfile, WithoutResponseTheModelFollowsTheTypeAndTheResonance) {
  for (const auto& [type, model] : {std::pair{"lra", ResponseModel::lra}, std::pair{"erm", ResponseModel::erm},
                                    std::pair{"voice_coil", ResponseModel::voice_coil}, std::pair{"ideal", ResponseModel::ideal}}) {
    const auto result = parse_actuator_profile(
        std::string("<actuator name=\"old\" type=\"") + type + "\">\n  <resonance hz=\"160\"/>\n</actuator>\n", "old.xml");
    ASSERT_TRUE(result.profile) << type;
    EXPECT_EQ(result.profile->response.model, model) << type;
    EXPECT_DOUBLE_EQ(result.profile->response.resonance_hz, 160.0) << type;
    EXPECT_DOUBLE_EQ(result.profile->response.q, ResponseParams{}.q) << type;
  }
}

TEST(ActuatorProfile, BandwidthGivesQWhereverTheResonanceIsWritten) {
  // <response> before <resonance>: Q = resonance / bandwidth all the same.
  const auto result = parse_actuator_profile(
      "<actuator name=\"x\" type=\"lra\">\n  <response bandwidth_hz=\"20\"/>\n  <resonance hz=\"170\"/>\n</actuator>\n", "bw.xml");
  ASSERT_TRUE(result.profile) << (result.errors.empty() ? "" : result.errors.front());
  EXPECT_DOUBLE_EQ(result.profile->response.q, 170.0 / 20.0);
  EXPECT_DOUBLE_EQ(result.profile->response.resonance_hz, 170.0);
}

TEST(ActuatorProfile, BadResponseFieldsAreErrorsAtTheirLine) {
  const struct {
    const char* response;
    const char* expected;
  } cases[] = {
      {"<response model=\"lra\" q=\"nan\"/>", "bad.xml:3: error: attribute 'q': 'nan' is NaN"},
      {"<response model=\"lra\" q=\"inf\"/>", "bad.xml:3: error: attribute 'q': 'inf' is infinite"},
      {"<response model=\"lra\" q=\"500\"/>", "bad.xml:3: error: attribute 'q' must be in [0.5, 200], got 500"},
      {"<response model=\"lra\" q=\"10\" bandwidth_hz=\"20\"/>", "bad.xml:3: error: <response> gives q or bandwidth_hz, not both"},
      {"<response model=\"lra\" bandwidth_hz=\"0\"/>", "bad.xml:3: error: attribute 'bandwidth_hz' must be in [0.875, 350], got 0"},
      {"<response model=\"lra\" Q=\"10\"/>", "bad.xml:3: error: attribute 'Q' does not belong to <response model=\"lra\">"},
      {"<response model=\"erm\" spin_up_ms=\"0\"/>", "bad.xml:3: error: attribute 'spin_up_ms' must be in [1, 2000], got 0"},
      {"<response model=\"erm\" low_hz=\"50\"/>", "bad.xml:3: error: attribute 'low_hz' does not belong to <response model=\"erm\">"},
      {"<response model=\"voice_coil\" low_hz=\"600\" high_hz=\"500\"/>", "bad.xml:3: error: <response> low_hz must be below high_hz"},
      {"<response model=\"voice_coil\" high_hz=\"1e9\"/>", "bad.xml:3: error: attribute 'high_hz' must be in [1, 20000], got 1e9"},
      {"<response model=\"piezo\"/>", "bad.xml:3: error: <response> model must be lra, erm, voice_coil or ideal, not 'piezo'"},
      {"<response/><response/>", "bad.xml:3: error: <actuator> has more than one <response>"},
  };
  for (const auto& c : cases) {
    const std::string xml = std::string("<actuator name=\"x\" type=\"lra\">\n  <resonance hz=\"175\"/>\n  ") + c.response + "\n</actuator>\n";
    const auto result = parse_actuator_profile(xml, "bad.xml");
    EXPECT_FALSE(result.profile) << c.response;
    ASSERT_FALSE(result.errors.empty()) << c.response;
    EXPECT_EQ(result.errors.front().rfind(c.expected, 0), 0u) << c.response << "\n" << result.errors.front();
  }
}

TEST(ActuatorProfile, GpioPinText) {
  const auto pin = parse_gpio_pin("gpiochip2:5");
  ASSERT_TRUE(pin);
  EXPECT_EQ(pin->chip, "gpiochip2");
  EXPECT_EQ(pin->line, 5u);
  EXPECT_FALSE(parse_gpio_pin("gpiochip2"));
  EXPECT_FALSE(parse_gpio_pin("gpiochip2:x"));
  EXPECT_FALSE(parse_gpio_pin(":3"));
}

}  // namespace
}  // namespace vimg
