// `vimg compare` as a user runs it: exit codes, messages, the three report forms, rendered
// signals as inputs, and SIGINT/SIGTERM leaving nothing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "storage/json_reader.hpp"
#include "study/report_predicted.hpp"
#include "tests/cli/run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";
const std::string kData = VIMG_TEST_DATA_DIR "/compare/";
const std::string kLra = VIMG_SOURCE_DIR "/assets/profiles/lra-175hz-drv2605l.xml";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class CompareCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_compare_cmd_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  test::CommandRun vimg(const std::string& args) {
    return test::run_command("cd '" + dir_.string() + "' && timeout 120 '" + kVimg + "' " + args);
  }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::size_t files_in_dir() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  fs::path dir_;
};

TEST_F(CompareCommand, HelpAndVersionExitZero) {
  const auto help = vimg("compare --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--actuator"), std::string::npos);
  EXPECT_NE(help.out.find("--gesture"), std::string::npos);
  const auto version = vimg("compare --version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("0."), std::string::npos);
}

TEST_F(CompareCommand, UsageErrorsExitTwo) {
  EXPECT_EQ(vimg("compare " + kData + "dot.vimg --out r.json").exit_code, 2);  // one input
  const auto ext = vimg("compare " + kData + "dot.vimg " + kData + "line.vimg --out r.txt");
  EXPECT_EQ(ext.exit_code, 2);
  EXPECT_NE(ext.out.find("vimg compare: error: --out must end in .json, .html or .csv"), std::string::npos) << ext.out;
  EXPECT_EQ(vimg("compare " + kData + "dot.vimg " + kData + "line.vimg").exit_code, 2);  // no --out
  EXPECT_EQ(vimg("compare " + kData + "dot.vimg " + kData + "line.vimg --out r.json --frobnicate").exit_code, 2);
  EXPECT_EQ(files_in_dir(), 0u);
  // A render CSV given as input is never overwritten by the report.
  write("s.csv", "time_s,drive\n0,0.5\n");
  const auto same = vimg("compare s.csv " + kData + "dot.vimg --out ./s.csv");
  EXPECT_EQ(same.exit_code, 2);
  EXPECT_NE(same.out.find("--out names an input"), std::string::npos) << same.out;
  EXPECT_EQ(read_text(dir_ / "s.csv"), "time_s,drive\n0,0.5\n");
}

TEST_F(CompareCommand, BadInputsExitOneWithFileAndLine) {
  const std::string bad = write("bad.vimg", "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"40\" height=\"40\">\n"
                                            "  <dot x=\"1\" y=\"1\" radius=\"-3\"/>\n</vibroimage>\n");
  auto r = vimg("compare " + kData + "dot.vimg bad.vimg --out r.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("bad.vimg:3: error"), std::string::npos) << r.out;
  write("g.csv", "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,1,1,,down\nzero,0,2,2,,up\n");
  r = vimg("compare " + kData + "dot.vimg " + kData + "line.vimg --gesture g.csv --out r.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("g.csv:3: error"), std::string::npos) << r.out;
  write("p.xml", "<actuator name=\"bad\" type=\"lra\">\n  <resonance hz=\"-5\"/>\n</actuator>\n");
  r = vimg("compare " + kData + "dot.vimg " + kData + "line.vimg --actuator p.xml --out r.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("p.xml:2: error"), std::string::npos) << r.out;
  r = vimg("compare " + kData + "dot.vimg missing.vimg --out r.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("missing.vimg"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "r.json"));
}

TEST_F(CompareCommand, ACanvasSizeMismatchExitsOneNamingTheSizes) {
  const auto r = vimg("compare " + kData + "dot.vimg " + kData + "dot_60x40.vimg --out r.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("dot.vimg 40 x 40 mm, dot_60x40.vimg 60 x 40 mm"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "r.json"));
}

TEST_F(CompareCommand, TheJsonReportHasTheMatricesAndTheWarnings) {
  fs::copy_file(kData + "surface.vimg", dir_ / "A.vimg");
  fs::copy_file(kData + "surface.vimg", dir_ / "B.vimg");
  const auto r = vimg("compare A.vimg B.vimg " + kData + "dot.vimg --out r.json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("vimg compare: warning: A.vimg ~ B.vimg: likely confused (p = 0.50)"), std::string::npos) << r.out;
  const auto parsed = parse_json(read_text(dir_ / "r.json"), "r.json");
  ASSERT_TRUE(parsed.value) << (parsed.diagnostics.empty() ? "" : parsed.diagnostics[0].to_string());
  const JsonValue& root = *parsed.value;
  for (const char* key : {"images", "stsim", "cue_distances_jnd", "distance_jnd", "predicted_confusion", "warnings", "actuator",
                          "exploration", "model"})
    EXPECT_NE(root.find(key), nullptr) << key;
  ASSERT_EQ(root.find("images")->items.size(), 3u);
  EXPECT_EQ(root.find("images")->items[0].text, "A.vimg");
  for (const char* key : {"stsim", "distance_jnd", "predicted_confusion"}) {
    const JsonValue& m = *root.find(key);
    ASSERT_EQ(m.items.size(), 3u) << key;
    for (const auto& row : m.items) ASSERT_EQ(row.items.size(), 3u) << key;
  }
  for (const auto& row : root.find("predicted_confusion")->items) {
    double sum = 0.0;
    for (const auto& cell : row.items) sum += cell.number;
    EXPECT_NEAR(sum, 1.0, 1e-9);
  }
  ASSERT_EQ(root.find("warnings")->items.size(), 1u);
  EXPECT_EQ(root.find("warnings")->items[0].text, "A.vimg ~ B.vimg: likely confused (p = 0.50)");
  EXPECT_EQ(root.find("exploration")->find("kind")->text, "standard");
  EXPECT_EQ(root.find("actuator")->find("name")->text, "ideal");
  // What `vimg study report --predicted` reads of it.
  const PredictedLoadResult predicted = load_predicted_confusion(dir_ / "r.json");
  ASSERT_TRUE(predicted.predicted) << (predicted.diagnostics.empty() ? "" : predicted.diagnostics[0].to_string());
  EXPECT_EQ(predicted.predicted->stems, (std::vector<std::string>{"A", "B", "dot"}));
  EXPECT_NEAR(predicted.predicted->matrix[0][1], 0.5, 1e-3);
}

TEST_F(CompareCommand, TheHtmlReportIsSelfContainedWithHeatMaps) {
  const auto r = vimg("compare " + kData + "dot.vimg " + kData + "line.vimg " + kData + "surface.vimg --actuator " + kLra +
                      " --out r.html");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string html = read_text(dir_ / "r.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("Predicted confusion"), std::string::npos);
  EXPECT_NE(html.find("surface.vimg"), std::string::npos);
  EXPECT_NE(html.find("lra-175hz-drv2605l"), std::string::npos);
  EXPECT_EQ(html.find("http"), std::string::npos);  // nothing fetched, not even a namespace URI
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
}

TEST_F(CompareCommand, TheCsvReportIsOneRowPerOrderedPair) {
  const auto r = vimg("compare " + kData + "dot.vimg " + kData + "line.vimg --out r.csv");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::istringstream csv(read_text(dir_ / "r.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "image_i,image_j,stsim,level_jnd,pitch_jnd,envelope_jnd,distance_jnd,predicted_p");
  double row_sum[2] = {0, 0};
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    const auto last_comma = line.rfind(',');
    row_sum[line.rfind(kData + "dot.vimg", 0) == 0 ? 0 : 1] += std::stod(line.substr(last_comma + 1));
  }
  EXPECT_EQ(rows, 4);
  EXPECT_NEAR(row_sum[0], 1.0, 1e-9);
  EXPECT_NEAR(row_sum[1], 1.0, 1e-9);
}

// A WAV and a CSV written by `vimg render --signal acceleration` are the image's own signal: compared
// with the image rendered under the same gesture on the same actuator, ST-SIM is 1 and all three are
// confused.
TEST_F(CompareCommand, RenderedSignalsAreComparedAsTheyAre) {
  write("g.csv", "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,2,20,,down\n0.4,0,38,20,,move\n0.8,0,2,20,,up\n");
  const std::string render = "render " + kData + "surface.vimg --gesture g.csv --signal acceleration --actuator " + kLra;
  ASSERT_EQ(vimg(render + " --out s.wav").exit_code, 0);
  ASSERT_EQ(vimg(render + " --out s.csv").exit_code, 0);
  const auto r = vimg("compare s.wav s.csv " + kData + "surface.vimg --gesture g.csv --actuator " + kLra + " --out r.json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto parsed = parse_json(read_text(dir_ / "r.json"), "r.json");
  ASSERT_TRUE(parsed.value);
  const JsonValue& stsim = *parsed.value->find("stsim");
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(stsim.items[i].items[j].number, 1.0, 1e-12) << i << "," << j;
  }
  EXPECT_EQ(parsed.value->find("warnings")->items.size(), 3u);
  EXPECT_EQ(parsed.value->find("kinds")->items[0].text, "wav");
  EXPECT_EQ(parsed.value->find("kinds")->items[1].text, "csv");
  // At another rate, the signal is refused with the way to render it at 8 kHz.
  ASSERT_EQ(vimg(render + " --rate 48000 --out fast.wav").exit_code, 0);
  const auto refused = vimg("compare fast.wav s.wav --out r2.json");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.out.find("fast.wav: error: the signal is sampled at 48000 Hz"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(dir_ / "r2.json"));
}

// A comparison that takes a while (a large canvas, several images) interrupted by a signal once it
// says the first of 32 signals is analysed (a state, not a time): exit 128 + signal, no report and
// no temporary in the folder.
TEST_F(CompareCommand, AnInterruptedComparisonWritesNothing) {
  const std::string image = write("big.vimg",
                                  "<?xml version=\"1.0\"?>\n<vibroimage version=\"1.0\" width=\"400\" height=\"400\">\n"
                                  "  <surface shape=\"rect\" x=\"10\" y=\"10\" width=\"380\" height=\"380\" period=\"2\"/>\n"
                                  "</vibroimage>\n");
  std::string inputs;
  for (int i = 0; i < 32; ++i) inputs += " big.vimg";  // seconds of work even in a release build
  for (const auto& [signal_name, expected] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    const std::string cmd = "cd '" + dir_.string() + "' && ('" + kVimg + "' compare" + inputs +
                            " --out r.json 2>err.txt & pid=$!; until grep -q ' of 32 signals analysed' err.txt; do "
                            "kill -0 $pid 2>/dev/null || break; sleep 0.01; done; kill -" + signal_name +
                            " $pid; wait $pid; status=$?; cat err.txt; rm -f err.txt; exit $status)";
    const auto r = test::run_command(cmd);
    EXPECT_NE(r.out.find("1 of 32 signals analysed"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("32 of 32 signals analysed"), std::string::npos) << "the signal came after the work\n" << r.out;
    EXPECT_EQ(r.exit_code, expected) << r.out;
    EXPECT_NE(r.out.find("interrupted; r.json not written"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir_ / "r.json"));
    EXPECT_EQ(files_in_dir(), 1u);  // big.vimg alone
  }
}

}  // namespace
}  // namespace vimg
