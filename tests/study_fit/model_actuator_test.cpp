// `vimg compare --model` and `vimg separate --model` check the actuator the model was fitted
// through (cli/compare_inputs.hpp): a model fitted through an actuator of another response is
// refused (exit 1, an error at the model's "actuator" line, nothing written); the same response is
// accepted whether the profile is named or given as a file; a model that does not record the
// response (of an older vimg) is used with a warning. Seen to fail with the check removed from
// load_model_argument: compare exits 0 and writes its report.
#include <gtest/gtest.h>

#include <string>

#include "tests/cli/run_command.hpp"
#include "tests/study_fit/fit_files.hpp"

namespace vimg::fit_test {
namespace {

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";

// A model fitted through `response` (the line of "actuator" is 4).
std::string model_through(const std::string& given, const std::string& response) {
  return "{\"format\": \"vimg-perception-model\", \"version\": 1,\n\"constants\": {\"temperature_jnd\": 1, \"lapse_rate\": 0.1, "
         "\"cue_weight\": {\"level\": 1, \"pitch\": 1, \"envelope\": 1}},\n\"fitted_on\": {\"study\": \"s.xml\",\n\"actuator\": \"" +
         given + "\"" + (response.empty() ? "" : ",\n\"actuator_response\": " + response) + "}}\n";
}

constexpr const char* kLra =
    "{\"model\": \"lra\", \"resonance_hz\": 175, \"q\": 10, \"low_hz\": 50, \"high_hz\": 500, \"spin_up_s\": 0.03, "
    "\"spin_down_s\": 0.045}";
constexpr const char* kIdeal =
    "{\"model\": \"ideal\", \"resonance_hz\": 175, \"q\": 10, \"low_hz\": 50, \"high_hz\": 500, \"spin_up_s\": 0.03, "
    "\"spin_down_s\": 0.045}";

class ModelActuator : public FitFolderTest {
 protected:
  void SetUp() override {
    FitFolderTest::SetUp();
    write_surface_study(dir_, "textures", {{"a", 2.0, 0.7}, {"b", 3.0, 0.7}}, 5, 20.0);
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name, std::ios::binary) << text; }
  test::CommandRun vimg(const std::string& arguments) {
    return test::run_command("cd '" + dir_.string() + "' && timeout 120 '" + kVimg + "' " + arguments);
  }
};

TEST_F(ModelActuator, CompareAndSeparateRefuseAModelFittedThroughAnotherActuator) {
  write("lra.json", model_through("lra-175hz-drv2605l", kLra));
  const test::CommandRun ideal = vimg("compare a.vimg b.vimg --model lra.json --out c.json");
  EXPECT_EQ(ideal.exit_code, 1) << ideal.out;
  EXPECT_NE(ideal.out.find("lra.json:4: error: the model was fitted through the actuator 'lra-175hz-drv2605l' (lra, 175 Hz, "
                           "Q 10), and the images are felt here through 'ideal' (ideal, 175 Hz)"),
            std::string::npos)
      << ideal.out;
  EXPECT_NE(ideal.out.find("give --actuator lra-175hz-drv2605l"), std::string::npos) << ideal.out;
  EXPECT_FALSE(fs::exists(dir_ / "c.json"));
  const test::CommandRun erm = vimg("compare a.vimg b.vimg --actuator erm-10mm --model lra.json --out c.json");
  EXPECT_EQ(erm.exit_code, 1) << erm.out;
  EXPECT_NE(erm.out.find("lra.json:4: error: the model was fitted through the actuator"), std::string::npos) << erm.out;
  const test::CommandRun separate = vimg("separate a.vimg b.vimg --actuator erm-10mm --model lra.json --out proposal");
  EXPECT_EQ(separate.exit_code, 1) << separate.out;
  EXPECT_NE(separate.out.find("lra.json:4: error: the model was fitted through the actuator"), std::string::npos)
      << separate.out;
  EXPECT_FALSE(fs::exists(dir_ / "proposal"));
}

TEST_F(ModelActuator, TheSameResponseIsAcceptedByNameOrByFile) {
  write("lra.json", model_through("lra-175hz-drv2605l", kLra));
  const std::string profile = VIMG_SOURCE_DIR "/assets/profiles/lra-175hz-drv2605l.xml";
  for (const std::string& actuator : {std::string("lra-175hz-drv2605l"), profile}) {
    const test::CommandRun r = vimg("compare a.vimg b.vimg --actuator '" + actuator + "' --model lra.json --out c.json");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(r.out.find("lra.json"), std::string::npos) << r.out;  // nothing to say about the model
  }
  write("ideal.json", model_through("ideal", kIdeal));
  const test::CommandRun r = vimg("compare a.vimg b.vimg --model ideal.json --out c.json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("ideal.json"), std::string::npos) << r.out;
}

TEST_F(ModelActuator, AModelThatDoesNotRecordTheResponseIsUsedWithAWarning) {
  write("old.json", model_through("erm-10mm", ""));
  const test::CommandRun r = vimg("compare a.vimg b.vimg --model old.json --out c.json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("old.json:4: warning: the model names the actuator 'erm-10mm' but not its response (a model of an "
                       "older vimg, or written by hand), so it cannot be checked against the actuator 'ideal' given here"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(fs::exists(dir_ / "c.json"));
  // Named as given here: nothing to warn about.
  const test::CommandRun same = vimg("compare a.vimg b.vimg --actuator erm-10mm --model old.json --out d.json");
  EXPECT_EQ(same.exit_code, 0) << same.out;
  EXPECT_EQ(same.out.find("old.json"), std::string::npos) << same.out;
}

}  // namespace
}  // namespace vimg::fit_test
