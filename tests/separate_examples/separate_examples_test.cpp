// `vimg separate` on the cases docs/separate.md states, at full size (60 x 110 mm canvases, the
// LRA): the confused set of four periods brought to the target (checked by `vimg compare` on the
// written files), --keep and --vary obeyed, the target out of reach along one dimension. They run
// in Release; under the sanitizers the same code runs on small canvases (tests/separate/).
#include "tests/separate/separate_fixture.hpp"

namespace vimg::separate_test {
namespace {

TEST_F(SeparateCommand, FourPeriodsThroughTheLraReachTheTarget) {
  const auto before = vimg("compare " + kFour + " --actuator " + kLra + " --out before.json");
  ASSERT_EQ(before.exit_code, 0) << before.out;
  EXPECT_NE(before.out.find("`vimg separate` on these images proposes which tactile parameters to change"),
            std::string::npos)
      << "vimg compare points to vimg separate when it warns\n" << before.out;
  double lowest = 1.0;
  for (const double p : compare_diagonal(read_json(dir_ / "before.json"))) lowest = std::min(lowest, p);
  EXPECT_LT(lowest, 0.9) << "the example set should be confused";

  const auto r = vimg("separate " + kFour + " --actuator " + kLra + " --out proposal");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("target reached"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\u2192"), std::string::npos) << "the changes are listed\n" << r.out;
  const JsonValue report = read_json(dir_ / "proposal/separate.json");
  EXPECT_EQ(report.find("outcome")->text, "reached");
  EXPECT_TRUE(fs::exists(dir_ / "proposal/separate.html"));
  std::string written;
  for (const char* name : {"texture_2_0mm.vimg", "texture_2_2mm.vimg", "texture_2_4mm.vimg", "texture_2_6mm.vimg"}) {
    ASSERT_TRUE(fs::exists(dir_ / "proposal" / name)) << name;
    written += " proposal/" + std::string(name);
  }
  const auto after = vimg("compare" + written + " --actuator " + kLra + " --out after.json");
  ASSERT_EQ(after.exit_code, 0) << after.out;
  const std::vector<double> diagonal = compare_diagonal(read_json(dir_ / "after.json"));
  ASSERT_EQ(diagonal.size(), 4u);
  const JsonValue* images = report.find("images");
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_GE(diagonal[i], 0.9) << i;
    EXPECT_NEAR(diagonal[i], images->items[i].find("identified_after")->number, 1e-9) << i;
  }
  // The inputs are untouched.
  EXPECT_NE(read_text(kExamples + "texture_2_0mm.vimg").find("period=\"2.0\""), std::string::npos);
}


TEST_F(SeparateCommand, KeepAndVaryAreObeyed) {
  std::string inputs;
  for (int i = 0; i < 4; ++i) inputs += " " + texture("t" + std::to_string(i) + ".vimg", 2.0 + 0.2 * i, 30, 30);
  const auto r = vimg("separate" + inputs + " --actuator " + kLra + " --out p --keep t0.vimg --vary period,gain");
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.out;
  const JsonValue report = read_json(dir_ / "p/separate.json");
  std::size_t changes = 0;
  for (const JsonValue& image : report.find("images")->items) {
    const bool kept = image.find("label")->text == "t0.vimg";
    EXPECT_EQ(image.find("kept")->boolean, kept);
    if (kept) {
      EXPECT_TRUE(image.find("changes")->items.empty());
    }
    for (const JsonValue& c : image.find("changes")->items) {
      const std::string p = c.find("parameter")->text;
      EXPECT_TRUE(p == "period" || p == "gain") << p;
      ++changes;
    }
  }
  EXPECT_GT(changes, 0u);
  // The kept image is written as it was.
  EXPECT_NE(read_text(dir_ / "p/t0.vimg").find("period=\"2\" relief=\"0.5\" pattern=\"sine\" gain=\"0.8\""),
            std::string::npos);
}


// Identification along one dimension saturates: eight textures on a small canvas through the LRA
// cannot all reach 90 % by gain alone, which moves the level cue alone (exit 3, the best set
// written, the limits said), and reach it with every tactile parameter allowed; period alone
// reaches it too, since a period moves the frequency, and through the LRA the level with it: two
// cues, whose information adds.
TEST_F(SeparateCommand, OneDimensionIsOutOfReachSeveralReach) {
  std::string inputs;
  for (int i = 0; i < 8; ++i) inputs += " " + texture("t" + std::to_string(i) + ".vimg", 2.0 + 0.1 * i, 30, 30);
  const auto narrow = vimg("separate" + inputs + " --actuator " + kLra + " --vary gain --out narrow");
  EXPECT_EQ(narrow.exit_code, 3) << narrow.out;
  EXPECT_NE(narrow.out.find("out of reach"), std::string::npos) << narrow.out;
  EXPECT_NE(narrow.out.find("dimensions allowed: gain"), std::string::npos) << narrow.out;
  EXPECT_NE(narrow.out.find("the number of images: 8"), std::string::npos) << narrow.out;
  EXPECT_EQ(read_json(dir_ / "narrow/separate.json").find("outcome")->text, "out_of_reach");
  EXPECT_TRUE(fs::exists(dir_ / "narrow/t7.vimg"));
  const auto wide = vimg("separate" + inputs + " --actuator " + kLra + " --out wide");
  EXPECT_EQ(wide.exit_code, 0) << wide.out;
  const auto period = vimg("separate" + inputs + " --actuator " + kLra + " --vary period --out period");
  EXPECT_EQ(period.exit_code, 0) << period.out;
}


}  // namespace
}  // namespace vimg::separate_test
