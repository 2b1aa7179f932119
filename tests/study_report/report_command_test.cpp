// `vimg study report` as a researcher runs it: trial files in, one report out (JSON, HTML, Markdown),
// and every malformed input refused at its line with nothing written (issue 20 section 3, issue 21
// section 2). The JSON is read back with the export tests' independent reader.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/cli/run_command.hpp"
#include "tests/export/json_reader.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;
using test::Json;

constexpr const char* kMatchingHeader = "participant,set,trial,presented,chosen,correct,rub_s,response_s,path_mm,time_utc\n";
constexpr const char* kLocationHeader =
    "participant,trial,metaphor,seed,target_x_mm,target_z_mm,mark_x_mm,mark_y_mm,mark_z_mm,error_mm,explore_s,time_utc\n";

std::string matching_row(const std::string& p, const std::string& set, int trial, const std::string& presented,
                         const std::string& chosen) {
  return p + "," + set + "," + std::to_string(trial) + "," + presented + "," + chosen + "," + (presented == chosen ? "1" : "0") +
         ",3.5,1.25,120,2026-11-25T16:38:51Z\n";
}

class ReportCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vimg_study_report_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // Worked by hand: set "complexity" (images dot, line, mixed, surface) and set "same" (a, b, c).
    //   complexity: p01 takes surface for line, p02 mixed for dot -> comparison (sorted by name)
    //     dot [2 0 0 0], line [0 2 0 0], mixed [1 0 1 0], surface [0 1 0 1]; 6 of 8 correct.
    //   same: p01 takes b for c -> a [2 0 0], b [0 0 1], c [0 0 1]; 3 of 4 correct.
    write("p01.trials.csv", std::string(kMatchingHeader) + matching_row("p01", "complexity", 1, "dot", "dot") +
                                matching_row("p01", "complexity", 2, "line", "line") +
                                matching_row("p01", "complexity", 3, "surface", "line") +
                                matching_row("p01", "complexity", 4, "mixed", "mixed") + matching_row("p01", "same", 5, "a", "a") +
                                matching_row("p01", "same", 6, "b", "c"));
    write("p02.trials.csv", std::string(kMatchingHeader) + matching_row("p02", "complexity", 1, "dot", "dot") +
                                matching_row("p02", "complexity", 2, "line", "line") +
                                matching_row("p02", "complexity", 3, "surface", "surface") +
                                matching_row("p02", "complexity", 4, "mixed", "dot") + matching_row("p02", "same", 5, "a", "a") +
                                matching_row("p02", "same", 6, "c", "c"));
    // Errors 5, 17 (roughness) and 3, 5 (transition cue), targets at the centre and at (30, -20).
    write("l01.location.csv", std::string(kLocationHeader) + "l01,1,roughness,11,0,0,3,0,4,5,20,2026-11-25T16:38:51Z\n" +
                                  "l01,2,roughness,12,30,-20,30,0,-3,17,20,2026-11-25T16:38:51Z\n" +
                                  "l01,3,transitionCue,13,0,0,0,0,3,3,20,2026-11-25T16:38:51Z\n" +
                                  "l01,4,transitionCue,14,30,-20,33,0,-16,5,20,2026-11-25T16:38:51Z\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name, std::ios::binary) << text; }
  std::string read(const std::string& name) {
    std::ifstream in(dir_ / name, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  test::CommandRun run(const std::string& arguments) {
    return test::run_command("cd '" + dir_.string() + "' && timeout 60 '" VIMG_BINARY_DIR "/cli/vimg' study report " + arguments);
  }
  Json report_json(const std::string& arguments) {
    const test::CommandRun r = run(arguments + " --out r.json");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return test::JsonReader::parse(read("r.json"));
  }

  fs::path dir_;
};

TEST_F(ReportCommand, MatchingJsonHasTheKeysAndTheHandWorkedCounts) {
  const Json j = report_json("p01.trials.csv p02.trials.csv");
  EXPECT_EQ(j["study"].string(), "matching");
  const auto& sets = j["sets"].array();
  ASSERT_EQ(sets.size(), 2u);
  const Json& a = sets[0];
  EXPECT_EQ(a["name"].string(), "complexity");
  ASSERT_EQ(a["images"].array().size(), 4u);
  EXPECT_EQ(a["images"].array()[2].string(), "mixed");
  const double expected[4][4] = {{2, 0, 0, 0}, {0, 2, 0, 0}, {1, 0, 1, 0}, {0, 1, 0, 1}};
  double total = 0;
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(a["comparison"].array()[i].array()[k].number(), expected[i][k]) << i << "," << k;
      total += a["comparison"].array()[i].array()[k].number();
    }
  }
  EXPECT_EQ(total, a["trials"].number());
  EXPECT_EQ(a["accuracy"].number(), 0.75);
  EXPECT_EQ(a["correct"].number() / a["trials"].number(), a["accuracy"].number());
  // SciPy 1.10.1: binomtest(6, 8).proportion_ci(0.95, method="wilson").
  EXPECT_NEAR(a["accuracy_ci95"].array()[0].number(), 0.40927543031016883, 1e-12);
  EXPECT_NEAR(a["accuracy_ci95"].array()[1].number(), 0.9285207872478909, 1e-12);
  EXPECT_EQ(a["chance"].number(), 0.25);
  const Json& dot = a["per_image"].array()[0];
  EXPECT_EQ(dot["image"].string(), "dot");
  EXPECT_EQ(dot["tp"].number(), 2);
  EXPECT_EQ(dot["fn"].number(), 0);
  EXPECT_EQ(dot["fp"].number(), 1);
  EXPECT_EQ(dot["tn"].number(), 5);
  EXPECT_EQ(dot["hit_rate"].number(), 1.0);
  EXPECT_EQ(dot["false_alarm_rate"].number(), 1.0 / 6.0);
  for (const Json& image : a["per_image"].array()) {
    EXPECT_EQ(image["tp"].number() + image["fn"].number() + image["fp"].number() + image["tn"].number(), 8);
  }
  const Json& b = sets[1];
  EXPECT_EQ(b["accuracy"].number(), 0.75);
  EXPECT_EQ(b["per_image"].array()[1]["tp"].number(), 0);  // b was never recognised
  EXPECT_EQ(b["participants"].array()[0]["accuracy"].number(), 0.5);
  EXPECT_EQ(b["participants"].array()[1]["accuracy"].number(), 1.0);
  // Per-participant accuracy: complexity 0.75, 0.75; same 0.5, 1.0 -> t = 0, df = 1, p = 1.
  EXPECT_EQ(j["ttest"]["t"].number(), 0.0);
  EXPECT_NEAR(j["ttest"]["df"].number(), 1.0, 1e-12);
  EXPECT_NEAR(j["ttest"]["p"].number(), 1.0, 1e-12);
  EXPECT_EQ(j["set_comparisons"].array().size(), 1u);
}

TEST_F(ReportCommand, LocationJsonHasTheKeys) {
  const Json j = report_json("l01.location.csv");
  EXPECT_EQ(j["study"].string(), "location");
  const auto& m = j["metaphors"].array();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0]["name"].string(), "roughness");
  EXPECT_EQ(m[0]["n"].number(), 2);
  EXPECT_EQ(m[0]["mean_mm"].number(), 11.0);
  EXPECT_NEAR(m[0]["sd_mm"].number(), std::sqrt(72.0), 1e-12);
  // SciPy 1.10.1: t.interval(0.99, 1, loc=11, scale=sqrt(72)/sqrt(2)).
  EXPECT_NEAR(m[0]["ci99_mm"].array()[0].number(), -370.9404469772439, 1e-9);
  EXPECT_NEAR(m[0]["ci99_mm"].array()[1].number(), 392.9404469772439, 1e-9);
  EXPECT_EQ(m[1]["mean_mm"].number(), 4.0);
  // The mean distance from the targets (0, 0) and (30, -20) to a point uniform in the 160 x 120 mm
  // box, by SciPy's dblquad: 53.8955420 and 61.7194036 mm.
  EXPECT_NEAR(j["chance_mm"].number(), (53.895542041632076 + 61.719403632715014) / 2.0, 1e-6);
  // SciPy 1.10.1: ttest_ind([5, 17], [3, 5], equal_var=False); df = 37^2 / (36^2 + 1) (Welch-Satterthwaite).
  EXPECT_NEAR(j["ttest"]["t"].number(), 1.150792911137501, 1e-12);
  EXPECT_NEAR(j["ttest"]["df"].number(), 1369.0 / 1297.0, 1e-12);
  EXPECT_NEAR(j["ttest"]["p"].number(), 0.44754373592012026, 1e-9);
  EXPECT_EQ(j["participants"].array().size(), 1u);
}

TEST_F(ReportCommand, MixedKindsGiveBothParts) {
  const Json j = report_json("p01.trials.csv l01.location.csv p02.trials.csv");
  EXPECT_EQ(j["study"].string(), "both");
  EXPECT_EQ(j["matching"]["sets"].array().size(), 2u);
  EXPECT_EQ(j["location"]["metaphors"].array().size(), 2u);
  EXPECT_EQ(j["inputs"].array().size(), 3u);
}

TEST_F(ReportCommand, HtmlIsSelfContainedWithItsFigures) {
  const test::CommandRun r = run("p01.trials.csv p02.trials.csv l01.location.csv --out r.html");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string html = read("r.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 3u);  // two comparison matrices and the bar chart
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
  EXPECT_NE(html.find("stroke-dasharray"), std::string::npos);  // the chance line
  EXPECT_NE(html.find(">surface</text>"), std::string::npos);   // labelled heat map
}

TEST_F(ReportCommand, MarkdownHasTheTables) {
  const test::CommandRun r = run("p01.trials.csv l01.location.csv --out r.md");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string md = read("r.md");
  EXPECT_NE(md.find("| image | TP | FN | FP | TN | hit rate | false-alarm rate |"), std::string::npos) << md;
  EXPECT_NE(md.find("| roughness | 2 | 11.0 |"), std::string::npos) << md;
}

TEST_F(ReportCommand, MalformedFilesAreRefusedAtTheirLineAndNothingIsWritten) {
  write("bad.trials.csv", std::string(kMatchingHeader) + matching_row("p03", "same", 1, "a", "a") + "p03,same,2,a,b,1,3,1,1,x\n");
  const test::CommandRun r = run("p01.trials.csv bad.trials.csv --out r.json");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("bad.trials.csv:3: error: "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "r.json"));
  write("other.csv", "time_s,finger,x_mm\n");
  const test::CommandRun other = run("other.csv --out r.html");
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_NE(other.out.find("other.csv:1: error: not a trial file"), std::string::npos) << other.out;
  const test::CommandRun missing = run("nonexistent.csv --out r.md");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.out.find("nonexistent.csv: error: "), std::string::npos) << missing.out;
  // The same participant's file twice: the second copy of a trial is named at its line.
  const test::CommandRun twice = run("p01.trials.csv p01.trials.csv --out r.json");
  EXPECT_EQ(twice.exit_code, 1);
  EXPECT_NE(twice.out.find("p01.trials.csv:2: error: participant 'p01' trial 1 is also at p01.trials.csv:2"), std::string::npos)
      << twice.out;
  write("empty.trials.csv", kMatchingHeader);
  const test::CommandRun empty = run("empty.trials.csv --out r.json");
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_NE(empty.out.find("no trials"), std::string::npos) << empty.out;
  write("c.json", "{\"images\": [\"a.vimg\"],\n \"predicted_confusion\": [[0.5]]}");
  const test::CommandRun predicted = run("p01.trials.csv --predicted c.json --out r.json");
  EXPECT_EQ(predicted.exit_code, 1);
  EXPECT_NE(predicted.out.find("c.json:2: error: "), std::string::npos) << predicted.out;
  for (const char* name : {"r.json", "r.html", "r.md"}) EXPECT_FALSE(fs::exists(dir_ / name)) << name;
}

TEST_F(ReportCommand, UsageErrorsAndHelp) {
  const test::CommandRun bad = run("p01.trials.csv --out r.txt");
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_NE(bad.out.find("vimg study report: error: --out must end in .html, .json or .md"), std::string::npos) << bad.out;
  EXPECT_EQ(run("p01.trials.csv").exit_code, 2);  // --out is required
  EXPECT_EQ(run("--out r.json").exit_code, 2);    // so is a trial file
  const test::CommandRun help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("docs/studies.md"), std::string::npos) << help.out;
  const test::CommandRun version = run("--version");
  EXPECT_EQ(version.exit_code, 0) << version.out;
  EXPECT_EQ(version.out.rfind("vimg ", 0), 0u) << version.out;
  EXPECT_FALSE(fs::exists(dir_ / "r.txt"));
}

// The primitives paper's study as 20 trial files (one per participant, 40 trials each): the report
// gives its Tables 1 and 2 and Table 6's accuracies exactly. Errors as in Tables 1-2: set
// complexity s3 -> s4 once (P04) and s4 -> s3 once (P05); set same s2 -> s4 and s4 -> s2 once each
// by P01, P02 and P03.
TEST_F(ReportCommand, ThePapersTablesFromTwentyTrialFiles) {
  std::string files;
  for (int p = 1; p <= 20; ++p) {
    const std::string id = std::string(p < 10 ? "P0" : "P") + std::to_string(p);
    std::string text = kMatchingHeader;
    int trial = 0;
    for (const std::string set : {"complexity", "same"}) {
      for (int rep = 0; rep < 5; ++rep) {
        for (int image = 1; image <= 4; ++image) {
          const std::string presented = "s" + std::to_string(image);
          std::string chosen = presented;
          if (rep == 2 && set == "complexity" && p == 4 && image == 3) chosen = "s4";
          if (rep == 2 && set == "complexity" && p == 5 && image == 4) chosen = "s3";
          if (rep == 4 && set == "same" && p <= 3 && image == 2) chosen = "s4";
          if (rep == 4 && set == "same" && p <= 3 && image == 4) chosen = "s2";
          text += matching_row(id, set, ++trial, presented, chosen);
        }
      }
    }
    write(id + ".trials.csv", text);
    files += " " + id + ".trials.csv";
  }
  const Json j = report_json(files);
  const double table1[4][4] = {{100, 0, 0, 0}, {0, 100, 0, 0}, {0, 0, 99, 1}, {0, 0, 1, 99}};
  const double table2[4][4] = {{100, 0, 0, 0}, {0, 97, 0, 3}, {0, 0, 100, 0}, {0, 3, 0, 97}};
  const auto& sets = j["sets"].array();
  ASSERT_EQ(sets.size(), 2u);
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(sets[0]["comparison"].array()[i].array()[k].number(), table1[i][k]) << i << "," << k;
      EXPECT_EQ(sets[1]["comparison"].array()[i].array()[k].number(), table2[i][k]) << i << "," << k;
    }
  }
  EXPECT_EQ(sets[0]["accuracy"].number(), 0.995);  // Table 6
  EXPECT_EQ(sets[1]["accuracy"].number(), 0.985);
  const Json& s2 = sets[1]["per_image"].array()[1];  // Table 5
  EXPECT_EQ(s2["tp"].number(), 97);
  EXPECT_EQ(s2["fn"].number(), 3);
  EXPECT_EQ(s2["fp"].number(), 3);
  EXPECT_EQ(s2["tn"].number(), 297);
  EXPECT_EQ(sets[0]["participants"].array().size(), 20u);
  EXPECT_EQ(sets[1]["participants"].array()[0]["accuracy"].number(), 0.9);
}

TEST_F(ReportCommand, PredictedConfusionSitsBesideTheMeasured) {
  write("c.json",
        "{\"images\": [\"x/a.vimg\", \"x/b.vimg\", \"x/c.vimg\"],\n"
        " \"predicted_confusion\": [[0.9, 0.05, 0.05], [0.1, 0.6, 0.3], [0.0, 0.2, 0.8]]}");
  const Json j = report_json("p01.trials.csv p02.trials.csv --predicted c.json");
  const Json& same = j["sets"].array()[1];
  ASSERT_TRUE(same.has("predicted"));
  EXPECT_EQ(same["predicted"]["predicted"].array()[1].array()[2].number(), 0.3);
  EXPECT_EQ(same["predicted"]["measured"].array()[1].array()[2].number(), 1.0);  // b was always taken for c
  EXPECT_EQ(same["predicted"]["off_diagonal_cells"].number(), 6);
  EXPECT_TRUE(same["predicted"]["correlation"].is_number());
  EXPECT_FALSE(j["sets"].array()[0].has("predicted"));  // it names none of the complexity set's images
}

}  // namespace
}  // namespace vimg
