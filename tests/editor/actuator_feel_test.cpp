// The actuator the editor designs for: which primitives are weak on it (the same answer and words
// as `vimg validate --actuator`), and changing the profile changes the marks.
#include "editor/core/actuator_feel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "storage/image_io.hpp"

namespace vimg::editor {
namespace {

namespace fs = std::filesystem;
const fs::path kProfiles = fs::path(VIMG_SOURCE_DIR) / "assets" / "profiles";
const fs::path kLra = kProfiles / "lra-175hz-drv2605l.xml";

// Surfaces at fullSpeed / period for each frequency (fullSpeed 100 mm/s), and a line at 40 Hz and
// one at 180 Hz inside a group.
Image test_image(const std::vector<double>& surface_hz) {
  std::string xml =
      "<vibroimage version=\"1.0\" width=\"200\" height=\"100\">\n"
      "  <interaction mass=\"0.01\" fullSpeed=\"100\" maxDeformation=\"1\"/>\n";
  for (std::size_t i = 0; i < surface_hz.size(); ++i) {
    xml += "  <surface id=\"s" + std::to_string(i) + "\" shape=\"rect\" x=\"" + std::to_string(10 * i) +
           "\" y=\"0\" width=\"8\" height=\"20\" period=\"" + std::to_string(100.0 / surface_hz[i]) +
           "\" relief=\"0.5\" pattern=\"sine\" gain=\"0.5\"/>\n";
  }
  xml += "  <group id=\"g\">\n"
         "    <line id=\"low\" x1=\"0\" y1=\"50\" x2=\"50\" y2=\"50\" width=\"2\" frequency=\"40\" damping=\"0.05\" gain=\"1\"/>\n"
         "    <line id=\"ok\" x1=\"0\" y1=\"60\" x2=\"50\" y2=\"60\" width=\"2\" frequency=\"180\" damping=\"0.05\" gain=\"1\"/>\n"
         "  </group>\n</vibroimage>\n";
  LoadResult r = parse_image_xml(xml, "test.vimg");
  EXPECT_TRUE(r.ok());
  return *r.image;
}

// The resonator of docs/actuators.md, in dB re its peak: -10 log10(1 + Q^2 (f/f0 - f0/f)^2).
double lra_db(double f, double f0, double q) {
  const double x = q * (f / f0 - f0 / f);
  return -10.0 * std::log10(1.0 + x * x);
}

TEST(ActuatorFeel, IdealByDefaultAndNothingIsWeak) {
  ActuatorFeel feel;
  EXPECT_EQ(feel.profile().response.model, ResponseModel::ideal);
  EXPECT_TRUE(feel.path().empty());
  EXPECT_TRUE(feel.marks(test_image({5, 20, 60, 175, 1000}), 1).empty());
}

TEST(ActuatorFeel, OnTheLraA20HzTextureIsWeakAnd175HzIsNot) {
  ActuatorFeel feel;
  ASSERT_TRUE(feel.choose(kLra).empty());
  const Image image = test_image({20, 175});
  const auto& marks = feel.marks(image, 1);
  ASSERT_EQ(marks.size(), 2u);  // s0 (20 Hz) and the 40 Hz line
  EXPECT_EQ(marks[0].id, "s0");
  EXPECT_NEAR(marks[0].frequency_hz, 20.0, 1e-6);
  EXPECT_EQ(marks[1].id, "low");
  EXPECT_EQ(feel.mark_of("s1"), nullptr);
  EXPECT_EQ(feel.mark_of("ok"), nullptr);
  ASSERT_NE(feel.mark_of("s0"), nullptr);
  // The words of `vimg validate --actuator`.
  EXPECT_NE(marks[0].message.find("surface 's0' at 20 Hz (fullSpeed 100 mm/s / period 5 mm) is "), std::string::npos)
      << marks[0].message;
  EXPECT_NE(marks[0].message.find("on actuator 'lra-175hz-drv2605l', outside its felt band"), std::string::npos);
  EXPECT_NE(marks[0].message.find("would be felt"), std::string::npos);
  EXPECT_NE(marks[1].message.find("line 'low' at 40 Hz is -32.4 dB"), std::string::npos) << marks[1].message;
  // The mark is where the element is.
  EXPECT_NEAR(marks[0].bounds.x0_mm, 0.0, 1e-9);
  EXPECT_NEAR(marks[0].bounds.y1_mm, 20.0, 1e-9);
}

// Property: across frequencies, a texture is marked exactly when the resonator's response there is
// more than 10 dB below its peak (Q 10 at 175 Hz, the profile's values).
TEST(ActuatorFeel, MarkedExactlyWhereTheResonatorIsMoreThan10DbDown) {
  ActuatorFeel feel;
  ASSERT_TRUE(feel.choose(kLra).empty());
  std::vector<double> hz;
  for (double f = 10.0; f < 2000.0; f *= 1.07) hz.push_back(f);
  const Image image = test_image(hz);
  feel.marks(image, 1);
  int weak = 0;
  for (std::size_t i = 0; i < hz.size(); ++i) {
    const double db = lra_db(hz[i], 175.0, 10.0);
    if (std::abs(db + 10.0) < 0.5) continue;  // the edge itself: the bilinear model differs by a hair
    const bool marked = feel.mark_of("s" + std::to_string(i)) != nullptr;
    EXPECT_EQ(marked, db < -10.0) << hz[i] << " Hz, " << db << " dB";
    weak += marked;
  }
  EXPECT_GT(weak, 50);
}

TEST(ActuatorFeel, ChangingTheProfileChangesTheMarks) {
  ActuatorFeel feel;
  const Image image = test_image({20, 175, 700});
  ASSERT_TRUE(feel.choose(kLra).empty());
  const std::uint64_t lra_generation = feel.generation();
  EXPECT_EQ(feel.marks(image, 7).size(), 3u);  // 20 Hz, 700 Hz and the 40 Hz line
  ASSERT_TRUE(feel.choose(kProfiles / "voice-coil-audio.xml").empty());
  EXPECT_NE(feel.generation(), lra_generation);
  // Same document (change count 7): the marks follow the profile. The voice coil's band is
  // 50-500 Hz with second-order corners: 20 Hz is weak, 175 and 700 Hz and the 40 Hz line are not.
  const auto& vc = feel.marks(image, 7);
  ASSERT_EQ(vc.size(), 1u);
  EXPECT_EQ(vc[0].id, "s0");
  EXPECT_EQ(feel.mark_of("low"), nullptr);
  feel.choose_ideal();
  EXPECT_TRUE(feel.marks(image, 7).empty());
}

TEST(ActuatorFeel, ABadProfileKeepsTheCurrentOneAndSaysWhereTheProblemIs) {
  ActuatorFeel feel;
  ASSERT_TRUE(feel.choose(kLra).empty());
  const fs::path bad = fs::temp_directory_path() / "vimg_feel_bad_profile.xml";
  std::ofstream(bad) << "<actuator name=\"x\" type=\"lra\">\n  <resonance hz=\"-5\"/>\n</actuator>\n";
  const auto errors = feel.choose(bad);
  ASSERT_FALSE(errors.empty());
  EXPECT_NE(errors[0].find(bad.string() + ":2: error:"), std::string::npos) << errors[0];
  EXPECT_EQ(feel.profile().name, "lra-175hz-drv2605l");
  EXPECT_EQ(feel.path(), kLra);
  const auto missing = feel.choose(fs::temp_directory_path() / "vimg_no_such_profile.xml");
  ASSERT_FALSE(missing.empty());
  EXPECT_NE(missing[0].find("error"), std::string::npos);
  fs::remove(bad);
}

TEST(ActuatorFeel, ListsTheShippedProfilesOfTheFirstFolderThatExists) {
  const auto files = profile_files({fs::path("/nonexistent/profiles"), kProfiles});
  ASSERT_GE(files.size(), 4u);
  EXPECT_TRUE(std::is_sorted(files.begin(), files.end()));
  EXPECT_NE(std::find(files.begin(), files.end(), kLra), files.end());
  for (const auto& f : files) EXPECT_EQ(f.extension(), ".xml");
}

}  // namespace
}  // namespace vimg::editor
