// `vimg separate` on rendered images (study/separate.hpp): the search against exhaustive search over
// the same steps with real renders, the proposal scored as `vimg compare` scores the written files,
// a distinct set left alone, and no primitive made barely felt.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "hal/felt_analysis.hpp"
#include "storage/image_io.hpp"
#include "study/compare.hpp"
#include "study/separate.hpp"
#include "study/separate_render_space.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kLra = VIMG_SOURCE_DIR "/assets/profiles/lra-175hz-drv2605l.xml";

class SeparateRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_separate_render_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A small canvas (a short exploration) with one sine texture of `period_mm`.
  fs::path texture(const std::string& name, double period_mm, const std::string& extra = "") {
    const fs::path p = dir_ / name;
    std::ofstream(p) << "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"20\" height=\"20\">\n"
                     << "  <surface id=\"t\" shape=\"rect\" x=\"2\" y=\"2\" width=\"16\" height=\"16\" period=\""
                     << period_mm << "\" relief=\"0.5\" pattern=\"sine\" gain=\"0.8\"/>\n"
                     << extra << "</vibroimage>\n";
    return p;
  }

  study::CompareActuator lra() {
    const ProfileLoadResult loaded = load_actuator_profile(kLra);
    EXPECT_TRUE(loaded.profile.has_value());
    study::CompareActuator a;
    a.name = loaded.profile->name;
    a.file = kLra;
    a.response = loaded.profile->response;
    return a;
  }

  fs::path dir_;
};

TEST_F(SeparateRender, ThreeTexturesWithinTenPercentOfExhaustiveSearch) {
  study::SeparateRequest q;
  q.inputs = {texture("a.vimg", 2.0), texture("b.vimg", 2.1), texture("c.vimg", 2.2)};
  q.vary = study::parse_tactile_parameter_list("period").set;
  const study::SeparateResult r = study::run_separate(q);
  ASSERT_TRUE(r.ok());
  ASSERT_FALSE(r.already_distinct);
  ASSERT_TRUE(r.reached);

  // The same space, every combination of the three images' period steps.
  std::vector<Image> originals;
  for (const auto& in : q.inputs) originals.push_back(*load_image_file(in).image);
  study::RenderSpaceOptions options;
  options.gestures = {r.before.exploration->gesture};
  options.response = q.actuator.response;
  study::RenderSeparationSpace space(originals, r.before.features, options);
  study::SeparationRequest search;
  search.vary = q.vary;
  std::vector<std::vector<study::SeparationSetting>> choices(3);
  for (int v = -6; v <= 6; ++v) {
    study::SeparationSetting s{};
    s[static_cast<std::size_t>(study::TactileParameter::period)] = static_cast<std::int8_t>(v);
    for (auto& c : choices) c.push_back(s);
  }
  const study::SeparationOutcome best = study::exhaustive_separation(space, search, choices);
  ASSERT_TRUE(best.reached);
  EXPECT_LE(r.total_change_jnd(), 1.10 * best.total_change_jnd)
      << "greedy " << r.total_change_jnd() << " JNDs, exhaustive " << best.total_change_jnd;
}

// The proposal's figures are those of `vimg compare` on the proposed images.
TEST_F(SeparateRender, TheProposalIsScoredAsCompareScoresTheWrittenImages) {
  study::SeparateRequest q;
  q.inputs = {texture("a.vimg", 1.0), texture("b.vimg", 1.1), texture("c.vimg", 1.2), texture("d.vimg", 1.3)};
  const study::SeparateResult r = study::run_separate(q);
  ASSERT_TRUE(r.ok());
  ASSERT_TRUE(r.reached);
  study::CompareRequest c;
  for (const auto& im : r.images) {
    const fs::path out = dir_ / ("proposed_" + fs::path(im.path).filename().string());
    ASSERT_FALSE(save_image_file(im.proposal, out).has_value());
    c.inputs.push_back(out);
  }
  const study::CompareResult after = study::run_compare(c);
  ASSERT_TRUE(after.ok());
  for (std::size_t i = 0; i < r.images.size(); ++i) {
    EXPECT_NEAR(after.predicted_confusion[i][i], r.images[i].identified_after, 1e-9) << i;
    EXPECT_GE(after.predicted_confusion[i][i], q.target) << i;
  }
}

TEST_F(SeparateRender, ADistinctSetGetsNoChange) {
  study::SeparateRequest q;
  q.inputs = {texture("a.vimg", 0.5), texture("b.vimg", 4.0, "<dot x=\"10\" y=\"10\" radius=\"3\"/>\n")};
  const study::SeparateResult r = study::run_separate(q);
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.already_distinct);
  for (const auto& im : r.images) EXPECT_TRUE(im.changes.empty());
}

// Textures felt on the LRA (periods inside its band at fullSpeed) stay felt: no proposal is one
// that `vimg validate --actuator` would warn about.
TEST_F(SeparateRender, FeltPrimitivesStayFelt) {
  const FeltAnalysisLoad felt = load_felt_analysis_file(kLra);
  ASSERT_TRUE(felt.analysis);
  study::SeparateRequest q;
  q.inputs = {texture("a.vimg", 0.56), texture("b.vimg", 0.57), texture("c.vimg", 0.58)};
  q.actuator = lra();
  q.weak_primitives = [&](const Image& im) { return weak_primitive_indices(im, *felt.analysis); };
  q.felt_band = felt.analysis->describe();
  for (const auto& in : q.inputs) ASSERT_TRUE(felt_warnings(*load_image_file(in).image, *felt.analysis).empty());
  const study::SeparateResult r = study::run_separate(q);
  ASSERT_TRUE(r.ok());
  ASSERT_FALSE(r.already_distinct);
  for (const auto& im : r.images) EXPECT_TRUE(felt_warnings(im.proposal, *felt.analysis).empty()) << im.label;
}

TEST_F(SeparateRender, ErrorsComeBackAsDiagnostics) {
  study::SeparateRequest q;
  q.inputs = {texture("a.vimg", 1.0), dir_ / "missing.vimg"};
  const study::SeparateResult r = study::run_separate(q);
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics.front().to_string().find("missing.vimg"), std::string::npos);
  study::SeparateRequest signal;
  signal.inputs = {texture("a.vimg", 1.0), dir_ / "s.wav"};
  EXPECT_FALSE(study::run_separate(signal).ok());
  study::SeparateRequest target;
  target.inputs = {texture("a.vimg", 1.0), texture("b.vimg", 1.1)};
  target.target = 1.0;
  EXPECT_FALSE(study::run_separate(target).ok());
}

}  // namespace
}  // namespace vimg
