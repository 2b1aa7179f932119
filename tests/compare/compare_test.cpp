// The prediction of study/compare.hpp on the cases: identical images are confused with an
// even split, a DOT, a LINE and a SURFACE are told apart, textures that differ only below the LRA's
// felt band are more confusable on the LRA than on the ideal actuator, canvases must match.
#include "storage/gesture_csv.hpp"
#include "study/compare.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <numeric>

#include "storage/actuator_profile.hpp"

namespace vimg::study {
namespace {

namespace fs = std::filesystem;

const fs::path kData = fs::path(VIMG_TEST_DATA_DIR) / "compare";

CompareRequest request_of(std::vector<fs::path> inputs) {
  CompareRequest r;
  r.inputs = std::move(inputs);
  return r;
}

CompareActuator lra() {
  const ProfileLoadResult p = load_actuator_profile(fs::path(VIMG_SOURCE_DIR) / "assets/profiles/lra-175hz-drv2605l.xml");
  EXPECT_TRUE(p.profile.has_value());
  return {p.profile->name, "lra-175hz-drv2605l.xml", p.profile->response};
}

void expect_rows_sum_to_one(const PerceptionMatrix& m) {
  for (const auto& row : m) EXPECT_NEAR(std::accumulate(row.begin(), row.end(), 0.0), 1.0, 1e-12);
}

class Compare : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_compare_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(Compare, TwoCopiesOfAnImageAreLikelyConfusedAndSplitTheirRowsEvenly) {
  fs::copy_file(kData / "surface.vimg", dir_ / "A.vimg");
  fs::copy_file(kData / "surface.vimg", dir_ / "B.vimg");
  const CompareResult r = run_compare(request_of({dir_ / "A.vimg", dir_ / "B.vimg", kData / "dot.vimg"}));
  ASSERT_TRUE(r.ok());
  expect_rows_sum_to_one(r.predicted_confusion);
  for (std::size_t row : {0u, 1u}) {
    EXPECT_NEAR(r.predicted_confusion[row][0], r.predicted_confusion[row][1], 1e-12);
    EXPECT_NEAR(r.predicted_confusion[row][0] + r.predicted_confusion[row][1], 1.0, 1e-3);
  }
  EXPECT_DOUBLE_EQ(r.stsim[0][1], 1.0);
  EXPECT_EQ(r.distance_jnd[0][1], 0.0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], "A.vimg ~ B.vimg: likely confused (p = 0.50)");
  ASSERT_EQ(r.likely_confused.size(), 1u);
  EXPECT_EQ(r.likely_confused[0].a, 0u);
  EXPECT_EQ(r.likely_confused[0].b, 1u);
}

TEST_F(Compare, ADotALineAndASurfaceArePredictedApart) {
  const CompareResult r = run_compare(request_of({kData / "dot.vimg", kData / "line.vimg", kData / "surface.vimg"}));
  ASSERT_TRUE(r.ok());
  expect_rows_sum_to_one(r.predicted_confusion);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GE(r.predicted_confusion[i][i], 0.9) << r.inputs[i].label;
  EXPECT_TRUE(r.warnings.empty());
}

// Through the LRA model a signal never returns to exact zero: where the DOT is felt, the LINE is only
// the LRA's decayed ring, and ST-SIM(dot | line) over those blocks is about 4e4 (the spectral term
// divides by the ring's tiny support). Each direction is bounded and the smaller taken.
TEST_F(Compare, ADotALineAndASurfaceArePredictedApartOnTheLra) {
  CompareRequest on_lra = request_of({kData / "dot.vimg", kData / "line.vimg", kData / "surface.vimg"});
  on_lra.actuator = lra();
  const CompareResult l = run_compare(on_lra);
  ASSERT_TRUE(l.ok());
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GE(l.predicted_confusion[i][i], 0.9) << l.inputs[i].label;
}

TEST_F(Compare, TexturesDifferingOnlyBelowTheLraBandAreMoreConfusableOnTheLra) {
  CompareRequest ideal = request_of({kData / "texture_10mm.vimg", kData / "texture_6mm.vimg"});
  CompareRequest on_lra = ideal;
  on_lra.actuator = lra();
  const CompareResult i = run_compare(ideal);
  const CompareResult l = run_compare(on_lra);
  ASSERT_TRUE(i.ok());
  ASSERT_TRUE(l.ok());
  EXPECT_LT(l.distance_jnd[0][1], i.distance_jnd[0][1]);
  EXPECT_GT(l.predicted_confusion[0][1], i.predicted_confusion[0][1]);
  EXPECT_GT(l.predicted_confusion[1][0], i.predicted_confusion[1][0]);
  EXPECT_TRUE(i.warnings.empty());
  EXPECT_EQ(l.warnings.size(), 1u);
  EXPECT_EQ(l.actuator.name, "lra-175hz-drv2605l");
}

TEST_F(Compare, ImagesOfDifferentCanvasSizesAreRefusedNamingTheSizes) {
  const CompareResult r = run_compare(request_of({kData / "dot.vimg", kData / "line.vimg", kData / "dot_60x40.vimg"}));
  EXPECT_FALSE(r.ok());
  ASSERT_EQ(r.diagnostics.size(), 1u);
  const std::string text = r.diagnostics[0].to_string();
  EXPECT_NE(text.find("dot_60x40.vimg: error: the canvas differs from dot.vimg's"), std::string::npos) << text;
  EXPECT_NE(text.find("dot.vimg 40 x 40 mm, line.vimg 40 x 40 mm, dot_60x40.vimg 60 x 40 mm"), std::string::npos) << text;
  EXPECT_TRUE(r.predicted_confusion.empty());
}

TEST_F(Compare, AnInputThatDoesNotLoadIsReportedAtItsLine) {
  std::ofstream(dir_ / "bad.vimg") << "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"40\" height=\"40\">\n"
                                      "  <dot x=\"1\" y=\"1\" radius=\"-3\"/>\n</vibroimage>\n";
  const CompareResult r = run_compare(request_of({kData / "dot.vimg", dir_ / "bad.vimg"}));
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].to_string().find("bad.vimg:3: error"), std::string::npos) << r.diagnostics[0].to_string();
}

TEST_F(Compare, InputsSharingAFileNameAreLabelledByTheirPaths) {
  fs::create_directories(dir_ / "x");
  fs::create_directories(dir_ / "y");
  fs::copy_file(kData / "dot.vimg", dir_ / "x/dot.vimg");
  fs::copy_file(kData / "line.vimg", dir_ / "y/dot.vimg");
  const CompareResult r = run_compare(request_of({dir_ / "x/dot.vimg", dir_ / "y/dot.vimg"}));
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.inputs[0].label, (dir_ / "x/dot.vimg").string());
  EXPECT_EQ(r.inputs[1].label, (dir_ / "y/dot.vimg").string());
}

TEST_F(Compare, TooFewInputsAreAnError) {
  EXPECT_FALSE(run_compare(request_of({kData / "dot.vimg"})).ok());
}

TEST_F(Compare, GivenGesturesReplaceTheExploration) {
  CompareRequest r = request_of({kData / "dot.vimg", kData / "line.vimg"});
  const GestureParseResult g = parse_gesture_csv(
      "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,2,20,,down\n0.5,0,38,20,,move\n1,0,2,20,,up\n", "g.csv");
  ASSERT_TRUE(g.ok());
  r.gestures = {{"g.csv", *g.gesture}, {"g.csv", *g.gesture}};
  const CompareResult c = run_compare(r);
  ASSERT_TRUE(c.ok());
  EXPECT_FALSE(c.exploration.has_value());
  EXPECT_EQ(c.gesture_files.size(), 2u);
  EXPECT_NEAR(c.inputs[0].duration_s, 2 * (1.0 + 0.25), 1e-3);  // each gesture and its tail
}

bool stop_now() { return true; }

TEST_F(Compare, AStopRequestEndsTheComparisonWithNothing) {
  CompareRequest r = request_of({kData / "dot.vimg", kData / "line.vimg"});
  r.should_stop = stop_now;
  const CompareResult c = run_compare(r);
  EXPECT_TRUE(c.interrupted);
  EXPECT_FALSE(c.ok());
  EXPECT_TRUE(c.predicted_confusion.empty());
}

}  // namespace
}  // namespace vimg::study
