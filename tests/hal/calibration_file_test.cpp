// DRV2605L calibration files and actuator profiles as hostile input: bounded reads, escaped
// messages, atomic writes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "storage/actuator_profile.hpp"
#include "storage/drv2605l_calibration_file.hpp"

namespace vimg {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::path(VIMG_BINARY_DIR) / "hal_calibration_file_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(CalibrationFile, SavedAtomicallyAndReadBack) {
  const auto path = scratch("lra.cal");
  std::filesystem::remove(path);
  Drv2605lCalibration c;
  c.resonance_hz = 171.25;
  c.a_cal_comp = 0x0C;
  c.a_cal_bemf = 0x9A;
  c.bemf_gain = 2;
  ASSERT_EQ(save_calibration(c, path), std::nullopt);
  const CalibrationLoadResult r = load_calibration(path);
  ASSERT_TRUE(r.calibration) << r.error();
  EXPECT_NEAR(r.calibration->resonance_hz, 171.25, 1e-3);
  EXPECT_EQ(r.calibration->a_cal_bemf, 0x9A);
  for (const auto& e : std::filesystem::directory_iterator(path.parent_path())) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "a temporary was left: " << e.path();
  }
}

TEST(CalibrationFile, ADeviceOrAHugeFileIsRefusedWithoutReadingIt) {
  const CalibrationLoadResult zero = load_calibration("/dev/zero");
  EXPECT_FALSE(zero.calibration);
  EXPECT_EQ(zero.error(), "/dev/zero: error: is not a regular file (a character device)");
  const auto big = scratch("big.cal");
  { std::ofstream(big) << std::string(kMaxCalibrationFileBytes + 1, '#'); }
  EXPECT_NE(load_calibration(big).error().find("(limit " + std::to_string(kMaxCalibrationFileBytes) + " bytes)"),
            std::string::npos);
  EXPECT_EQ(load_calibration(scratch("missing.cal")).error(), "");  // no file: nothing to restore, no error
}

TEST(CalibrationFile, MessagesQuoteValuesSafely) {
  const CalibrationLoadResult r = parse_calibration("resonance_hz=175\na_cal_comp=\x1b[2J\n", "x.cal");
  EXPECT_EQ(r.error(), "x.cal:2: error: 'a_cal_comp' must be a byte value, not '\\x1B[2J'");
  EXPECT_EQ(parse_calibration("resonance_hz=nan\n", "x.cal").error(), "x.cal:1: error: resonance_hz must be a positive number");
}

TEST(ActuatorProfileFile, ADeviceIsRefusedWithoutReadingIt) {
  const ProfileLoadResult r = load_actuator_profile("/dev/zero");
  ASSERT_FALSE(r.profile);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors.front(), "/dev/zero: error: is not a regular file (a character device)");
}

TEST(ActuatorProfileFile, AnElementWithThousandsOfAttributesIsRefusedBeforeParsing) {
  std::string xml = "<actuator";
  for (int i = 0; i < 5000; ++i) xml += " a" + std::to_string(i) + "=\"1\"";
  xml += "/>";
  const ProfileLoadResult r = parse_actuator_profile(xml, "p.xml");
  ASSERT_FALSE(r.profile);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors.front().find("p.xml:1: error: "), std::string::npos) << r.errors.front();
  EXPECT_NE(r.errors.front().find("(limit 64)"), std::string::npos) << r.errors.front();
}

}  // namespace
}  // namespace vimg
