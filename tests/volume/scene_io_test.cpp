#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "primitives/volume/study_set.hpp"
#include "storage/volume/study_writer.hpp"
#include "storage/volume/volume_scene_io.hpp"

namespace vimg {
namespace {

std::string first_message(const std::vector<Diagnostic>& d) { return d.empty() ? std::string() : d.front().to_string(); }

TEST(VolumeSceneXml, StudySceneRoundTrips) {
  const VolumeScene scene = make_study_set(3).scene;
  const std::string xml = write_volume_scene_xml(scene);
  const VolumeSceneParseResult r = parse_volume_scene_xml(xml, "s.xml");
  ASSERT_TRUE(r.ok()) << first_message(r.diagnostics);
  EXPECT_EQ(*r.scene, scene);
  EXPECT_EQ(write_volume_scene_xml(*r.scene), xml);
}

TEST(VolumeSceneXml, EveryModeAndOmegaFormRoundTrip) {
  VolumeScene scene = make_study_set(4).scene;
  for (auto mode : {KinaestheticMode::gradient_force, KinaestheticMode::yielding_surface}) {
    scene.kinaesthetic->mode = mode;
    scene.kinaesthetic->data = "feature";
    scene.kinaesthetic->scale_N_mm = -0.25;
    scene.roughness[0].omega_given_as_period = false;
    scene.roughness[0].omega_points = {{-1.0, 3.0}, {2.5, 10.0}};
    const VolumeSceneParseResult r = parse_volume_scene_xml(write_volume_scene_xml(scene), "s.xml");
    ASSERT_TRUE(r.ok()) << first_message(r.diagnostics);
    EXPECT_EQ(*r.scene, scene);
  }
}

struct BadScene {
  std::string body;      // inside <volumeScene>
  std::string expected;  // start of the first message
};

TEST(VolumeSceneXml, ErrorsNameFileAndLine) {
  const std::string data = "<scalarData id=\"s\" file=\"s.nrrd\"/>\n<vectorData id=\"v\" file=\"v.nrrd\"/>\n";
  const std::vector<BadScene> cases = {
      {data + "<kinaesthetic mode=\"magnet\" data=\"v\"/>", "x.xml:4: error: mode must be"},
      {data + "<kinaesthetic mode=\"vectorGuidance\" data=\"s\"/>", "x.xml:4: error: <kinaesthetic> needs vector data"},
      {data + "<transitionCue data=\"nope\"/>", "x.xml:4: error: <transitionCue> names data 'nope'"},
      {data + "<transitionCue data=\"s\" colour=\"red\"/>", "x.xml:4: error: unknown attribute 'colour'"},
      {data + "<transitionCue data=\"s\" frequency=\"-3\"/>", "x.xml:4: error: attribute 'frequency' must be > 0"},
      {data + "<transitionCue data=\"s\" amplitude=\"lots\"/>", "x.xml:4: error: attribute 'amplitude': 'lots'"},
      {data + "<roughness data=\"s\">\n<period value=\"1\" mm=\"1\"/>\n<period value=\"1\" mm=\"2\"/>\n<amplitude value=\"0\" N=\"1\"/>\n</roughness>",
       "x.xml:6: error: transfer function values must increase strictly"},
      {data + "<roughness data=\"s\">\n<amplitude value=\"0\" N=\"1\"/>\n</roughness>", "x.xml:4: error: <roughness> needs <period> or <omega>"},
      {data + "<device rate=\"8000\"/>", "x.xml:4: error: attribute 'rate' must be at most 4000 Hz"},
      {data + "<device maxStiffness=\"100\"/>\n<kinaesthetic mode=\"yieldingSurface\" data=\"s\" stiffness=\"300\"/>",
       "x.xml:5: error: stiffness exceeds the device's maxStiffness"},
      {data + "<scalarData id=\"s\" file=\"t.nrrd\"/>", "x.xml:4: error: duplicate data id 's' (first on line 2)"},
      {data + "<hologram/>", "x.xml:4: error: unknown element <hologram>"},
      {data + "<device", "x.xml:4: error: not well-formed XML: a tag that is not closed"},
  };
  for (const auto& c : cases) {
    const std::string xml = "<volumeScene version=\"1.0\">\n" + c.body + "\n</volumeScene>\n";
    const VolumeSceneParseResult r = parse_volume_scene_xml(xml, "x.xml");
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(first_message(r.diagnostics).rfind(c.expected, 0), 0u)
        << "got: " << first_message(r.diagnostics) << "\nwanted: " << c.expected;
  }
  EXPECT_EQ(first_message(parse_volume_scene_xml("<scene/>", "y.xml").diagnostics), "y.xml:1: error: the root element must be <volumeScene>");
}

TEST(VolumeSceneXml, WarnsWhenTheVibrationIsNotBelowTheKinaestheticStrength) {
  VolumeScene scene = make_study_set(2).scene;  // guidance resists with 1.5 N
  EXPECT_TRUE(parse_volume_scene_xml(write_volume_scene_xml(scene), "s.xml").diagnostics.empty());
  scene.transition_cues[0].amplitude_N = 1.5;
  const VolumeSceneParseResult r = parse_volume_scene_xml(write_volume_scene_xml(scene), "s.xml");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(first_message(r.diagnostics),
            "s.xml:15: warning: transition cue amplitude 1.5 N is not below the kinaesthetic strength 1.5 N: "
            "the vibration may mask the structure");
}

class TempDir {
 public:
  TempDir() : path_(std::filesystem::temp_directory_path() / ("vimg_volume_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    std::filesystem::remove_all(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

TEST(VolumeSceneFile, LoadsTheStudySetWithItsData) {
  TempDir dir;
  const StudySet set = make_study_set(12);
  ASSERT_FALSE(write_study_set(set, dir.path()).has_value());
  const VolumeSceneLoadResult r = load_volume_scene_file(dir.path() / kStudySceneFileName);
  ASSERT_TRUE(r.ok()) << first_message(r.diagnostics);
  EXPECT_EQ(r.loaded->scalars.at("feature")->values(), set.feature.values());
  EXPECT_EQ(r.loaded->vectors.at("flow")->components(), set.flow.components());
}

TEST(VolumeSceneFile, DataOfTheWrongKindOrMissingIsAnError) {
  TempDir dir;
  ASSERT_FALSE(write_study_set(make_study_set(1), dir.path()).has_value());
  std::filesystem::rename(dir.path() / "flow.nrrd", dir.path() / "tmp.nrrd");
  std::filesystem::rename(dir.path() / "feature.nrrd", dir.path() / "flow.nrrd");
  std::filesystem::rename(dir.path() / "tmp.nrrd", dir.path() / "feature.nrrd");
  const auto scene = (dir.path() / kStudySceneFileName).string();
  VolumeSceneLoadResult r = load_volume_scene_file(scene);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(first_message(r.diagnostics), scene + ":3: error: data 'feature' is declared scalar but feature.nrrd holds vectors");
  std::filesystem::remove(dir.path() / "flow.nrrd");
  r = load_volume_scene_file(scene);
  EXPECT_FALSE(r.ok());
  bool named = false;
  for (const auto& d : r.diagnostics) named = named || d.to_string() == scene + ":4: error: cannot load data 'flow' from " + (dir.path() / "flow.nrrd").string();
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace vimg
