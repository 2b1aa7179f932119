// `vimg gesture predict` and `vimg render --touch-latency-ms` as a user runs them: a touch log
// imported and predicted, one output row per input row, causal across a cut file, and usage and
// input errors exit 2 and 1 with their messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

const std::string kVimg = VIMG_BINARY_DIR "/cli/vimg";

struct Temp {
  fs::path dir = fs::temp_directory_path() / ("vimg_predict_" + std::to_string(::getpid()));
  Temp() { fs::create_directories(dir); }
  ~Temp() { fs::remove_all(dir); }
  std::string at(const std::string& name) const { return (dir / name).string(); }
};

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(GesturePredictCommand, ATouchLogImportsAndEveryRowIsPredictedCausally) {
  Temp t;
  const std::string log = VIMG_TEST_DATA_DIR "/touch-latency-henze2017/FittsTasks-participant1.txt";
  const auto imported = test::run_command(kVimg + " gesture import '" + log + "' --px-per-mm 12.72 --out " + t.at("g.csv"));
  ASSERT_EQ(imported.exit_code, 0) << imported.out;
  const std::vector<std::string> gesture = lines_of(t.at("g.csv"));
  ASSERT_GT(gesture.size(), 1000u);
  const auto predicted = test::run_command(kVimg + " gesture predict " + t.at("g.csv") + " --ahead-ms 33.3 --out " + t.at("p.csv"));
  ASSERT_EQ(predicted.exit_code, 0) << predicted.out;
  const std::vector<std::string> rows = lines_of(t.at("p.csv"));
  ASSERT_EQ(rows.size(), gesture.size());
  EXPECT_EQ(rows[0], "time_s,finger,x_mm,y_mm,predicted_x_mm,predicted_y_mm");
  // Cut the gesture after 600 rows: each row before the cut's last stroke keeps its prediction.
  std::vector<std::string> cut(gesture.begin(), gesture.begin() + 601);
  std::string text;
  for (const std::string& line : cut) text += line + "\n";
  write(t.at("cut.csv"), text);
  const auto cut_run = test::run_command(kVimg + " gesture predict " + t.at("cut.csv") + " --ahead-ms 33.3 --out " + t.at("q.csv"));
  ASSERT_EQ(cut_run.exit_code, 0) << cut_run.out;
  const std::vector<std::string> cut_rows = lines_of(t.at("q.csv"));
  ASSERT_EQ(cut_rows.size(), 601u);
  std::size_t same = 0;
  for (std::size_t i = 1; i < cut_rows.size(); ++i) same += cut_rows[i] == rows[i] ? 1 : 0;
  // Only the cut's last row (now an up: its own position) may differ.
  EXPECT_GE(same, cut_rows.size() - 2);
}

TEST(GesturePredictCommand, UsageErrorsExit2AndBadInputExits1WithItsLine) {
  Temp t;
  write(t.at("bad.csv"), "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,1,1,1,down\nzero,0,1,1,1,move\n");
  const auto bad = test::run_command(kVimg + " gesture predict " + t.at("bad.csv") + " --ahead-ms 50 --out " + t.at("o.csv"));
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  EXPECT_NE(bad.out.find(t.at("bad.csv") + ":3: error:"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(t.at("o.csv")));
  for (const std::string& args : {std::string(" --ahead-ms -1"), std::string(" --ahead-ms 5000"), std::string(" --ahead-ms nan"),
                                  std::string(" --ahead-ms 50 --model lstm"), std::string("")}) {
    const auto run = test::run_command(kVimg + " gesture predict " + t.at("bad.csv") + args + " --out " + t.at("o.csv"));
    EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.out;
  }
  EXPECT_EQ(test::run_command(kVimg + " gesture predict --help").exit_code, 0);
}

// The first time_s of a time_s,drive CSV whose drive is not 0.
double first_drive_s(const std::string& path) {
  const std::vector<std::string> lines = lines_of(path);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::size_t comma = lines[i].find(',');
    if (std::stod(lines[i].substr(comma + 1)) != 0.0) return std::stod(lines[i].substr(0, comma));
  }
  return -1.0;
}

TEST(RenderTouchLatency, ThePanelOptionsAreCheckedAndCompensationBringsTheOnsetBack) {
  Temp t;
  const std::string image = VIMG_SOURCE_DIR "/assets/examples/smiley.vimg";
  ASSERT_EQ(test::run_command(kVimg + " gesture line --from 5,40 --to 75,40 --speed 150 --rate 60 --out " + t.at("g.csv")).exit_code, 0);
  const std::string base = kVimg + " render " + image + " --gesture " + t.at("g.csv");
  EXPECT_EQ(test::run_command(base + " --touch-prediction off --out " + t.at("x.csv")).exit_code, 2);
  EXPECT_EQ(test::run_command(base + " --touch-latency-ms 900 --out " + t.at("x.csv")).exit_code, 2);
  ASSERT_EQ(test::run_command(base + " --out " + t.at("exact.csv")).exit_code, 0);
  ASSERT_EQ(test::run_command(base + " --touch-latency-ms 60 --out " + t.at("on.csv")).exit_code, 0);
  ASSERT_EQ(test::run_command(base + " --touch-latency-ms 60 --touch-prediction off --out " + t.at("off.csv")).exit_code, 0);
  const double exact = first_drive_s(t.at("exact.csv")), on = first_drive_s(t.at("on.csv")), off = first_drive_s(t.at("off.csv"));
  ASSERT_GT(exact, 0.0);
  EXPECT_NEAR(off - exact, 0.06, 1.0 / 60.0) << "the late panel delays the first contact by its latency";
  EXPECT_LT(std::abs(on - exact), 0.5 * (off - exact)) << "compensation brings it back";
}

TEST(RenderProgress, ARenderOfMoreThanAMinuteOfGestureReportsItsProgress) {
  Temp t;
  // 10 mm at 0.125 mm/s: 80 s of gesture.
  ASSERT_EQ(test::run_command(kVimg + " gesture line --from 5,40 --to 15,40 --speed 0.125 --rate 60 --out " + t.at("g.csv")).exit_code, 0);
  const auto run = test::run_command(kVimg + " render " VIMG_SOURCE_DIR "/assets/examples/smiley.vimg --gesture " + t.at("g.csv") +
                                     " --rate 1000 --out " + t.at("o.wav"));
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("vimg render: 30 of 80 s rendered"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("vimg render: 60 of 80 s rendered"), std::string::npos) << run.out;
  // A short render stays quiet.
  ASSERT_EQ(test::run_command(kVimg + " gesture line --from 5,40 --to 15,40 --speed 100 --out " + t.at("s.csv")).exit_code, 0);
  EXPECT_EQ(test::run_command(kVimg + " render " VIMG_SOURCE_DIR "/assets/examples/smiley.vimg --gesture " + t.at("s.csv") +
                              " --out " + t.at("s.wav")).out, "");
}

}  // namespace
}  // namespace vimg
