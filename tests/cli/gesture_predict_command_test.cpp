// `vimg gesture predict` and `vimg render --touch-latency-ms` as a user runs them: every output row,
// for every model and two horizons, is the library's prediction from that stroke's rows up to it
// alone (causal, and at the horizon asked for); a touch log imports and predicts the same way; usage
// and input errors exit 2 and 1 with their messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../touch_prediction/every_model.hpp"
#include "primitives/touch_prediction/finger_predictor.hpp"
#include "run_command.hpp"
#include "storage/gesture_csv.hpp"

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

struct OutputRow {
  double time_s = 0.0;
  int finger = 0;
  double x_mm = 0.0, y_mm = 0.0, predicted_x_mm = 0.0, predicted_y_mm = 0.0;
};

std::vector<OutputRow> output_rows(const std::string& path) {
  std::vector<OutputRow> rows;
  const std::vector<std::string> lines = lines_of(path);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream cells(lines[i]);
    std::string c[6];
    for (std::string& cell : c) std::getline(cells, cell, ',');
    rows.push_back({std::stod(c[0]), std::stoi(c[1]), std::stod(c[2]), std::stod(c[3]), std::stod(c[4]), std::stod(c[5])});
  }
  return rows;
}

// What docs/latency.md promises for each row, computed with the library: a down or up row gives its
// own position; row k of a stroke otherwise gives predict_finger() of a history holding that
// stroke's rows 0..k alone, `ahead_s` ahead. Per finger, in the file's order.
std::map<int, std::vector<OutputRow>> expected_rows(const Gesture& g, double ahead_s, TouchPredictionModel model) {
  std::map<int, std::vector<OutputRow>> rows;
  for (const GestureStroke& s : g.strokes) {
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const GesturePoint& p = s.points[k];
      PredictedPosition q{p.x_mm, p.y_mm};
      if (k > 0 && k + 1 < s.points.size()) {
        FingerHistory prefix;
        for (std::size_t i = 0; i <= k; ++i) add_finger_event(prefix, s.points[i].time_s, s.points[i].x_mm, s.points[i].y_mm);
        q = predict_finger(prefix, ahead_s, model);
      }
      rows[s.finger].push_back({p.time_s, s.finger, p.x_mm, p.y_mm, q.x_mm, q.y_mm});
    }
  }
  return rows;
}

// The command's rows against the library's, row by row: the rows come out in the gesture file's
// order, and each prediction equals the library's within print precision (the file prints the
// shortest text that reads back exactly; 1e-9 mm leaves room for nothing else). Returns how many
// rows were predicted away from their own position.
std::size_t expect_rows_as_the_library(const std::string& gesture_path, const std::string& out_path, double ahead_s,
                                       TouchPredictionModel model) {
  const GestureParseResult g = load_gesture_file(gesture_path);
  EXPECT_TRUE(g.ok());
  if (!g.ok()) return 0;
  std::map<int, std::vector<OutputRow>> expected = expected_rows(*g.gesture, ahead_s, model);
  std::map<int, std::size_t> next;
  const std::vector<OutputRow> rows = output_rows(out_path);
  std::size_t total = 0, moved = 0, wrong = 0;
  for (const auto& [finger, list] : expected) total += list.size();
  EXPECT_EQ(rows.size(), total);
  const std::string what = std::string(touch_prediction_model_name(model)) + " " + std::to_string(ahead_s) + " s: ";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const OutputRow& r = rows[i];
    if (i > 0) {
      EXPECT_LE(rows[i - 1].time_s, r.time_s) << what << "row " << i;
    }
    std::vector<OutputRow>& list = expected[r.finger];
    const std::size_t k = next[r.finger]++;
    if (k >= list.size()) { ADD_FAILURE() << what << "an extra row " << i; return moved; }
    const OutputRow& e = list[k];
    const bool same = r.time_s == e.time_s && r.x_mm == e.x_mm && r.y_mm == e.y_mm &&
                      std::abs(r.predicted_x_mm - e.predicted_x_mm) <= 1e-9 && std::abs(r.predicted_y_mm - e.predicted_y_mm) <= 1e-9;
    if (!same && wrong++ < 3) {
      ADD_FAILURE() << what << "row " << i << " (finger " << r.finger << ", t " << r.time_s << "): predicted ("
                    << r.predicted_x_mm << ", " << r.predicted_y_mm << "), the library from the rows up to it ("
                    << e.predicted_x_mm << ", " << e.predicted_y_mm << ")";
    }
    moved += std::hypot(e.predicted_x_mm - e.x_mm, e.predicted_y_mm - e.y_mm) > 0.1 ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u) << what << "rows that differ from the library's prediction";
  return moved;
}

// Two fingers at irregular times (2-30 ms apart, some 0.3 ms bursts), on curves that speed up, slow
// down and stop; finger 0 lifts and touches again. Numbers printed in full (%.17g).
std::string irregular_gesture_csv() {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  struct Row { double t; int finger; double x, y; const char* phase; };
  std::vector<Row> rows;
  auto stroke = [&](int finger, double t, double end_s, double x, double y) {
    double heading = 6.28 * unit(rng);
    for (bool first = true; t < end_s; first = false) {
      const double speed = 150.0 * (1.0 + std::sin(7.0 * t)) * (std::fmod(t, 0.5) < 0.4 ? 1.0 : 0.0);
      const double dt = unit(rng) < 0.15 ? 0.0003 : 0.002 + 0.028 * unit(rng);
      heading += 4.0 * std::sin(3.0 * t) * dt;
      x += speed * dt * std::cos(heading);
      y += speed * dt * std::sin(heading);
      t += dt;
      rows.push_back({t, finger, x, y, first ? "down" : t >= end_s ? "up" : "move"});
    }
  };
  stroke(0, 0.0, 0.9, 40.0, 40.0);
  stroke(1, 0.05, 1.4, 60.0, 30.0);
  stroke(0, 1.0, 1.6, 20.0, 50.0);
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.t < b.t; });
  std::string text = "time_s,finger,x_mm,y_mm,pressure,phase\n";
  char line[200];
  for (const Row& r : rows) {
    std::snprintf(line, sizeof line, "%.17g,%d,%.17g,%.17g,1,%s\n", r.t, r.finger, r.x, r.y, r.phase);
    text += line;
  }
  return text;
}

TEST(GesturePredictCommand, EveryRowIsTheLibrarysPredictionFromTheRowsUpToItAtTheHorizonAsked) {
  Temp t;
  write(t.at("g.csv"), irregular_gesture_csv());
  for (TouchPredictionModel m : test::every_touch_prediction_model()) {
    for (double ahead_ms : {33.0, 67.0}) {
      const std::string name(touch_prediction_model_name(m));
      const auto run = test::run_command(kVimg + " gesture predict " + t.at("g.csv") + " --ahead-ms " + std::to_string(ahead_ms) +
                                         " --model " + name + " --out " + t.at("p.csv"));
      ASSERT_EQ(run.exit_code, 0) << run.out;
      const std::size_t moved = expect_rows_as_the_library(t.at("g.csv"), t.at("p.csv"), ahead_ms * 1e-3, m);
      // Predicting "ahead" means something here: most rows of a moving finger move.
      if (m != TouchPredictionModel::none) {
        EXPECT_GT(moved, 100u) << name;
      }
    }
  }
  // Without --model: the default model, whichever it is.
  const auto run = test::run_command(kVimg + " gesture predict " + t.at("g.csv") + " --ahead-ms 50 --out " + t.at("d.csv"));
  ASSERT_EQ(run.exit_code, 0) << run.out;
  expect_rows_as_the_library(t.at("g.csv"), t.at("d.csv"), 0.05, kDefaultTouchPredictionModel);
}

TEST(GesturePredictCommand, AnImportedTouchLogIsPredictedRowByRowAsTheLibraryDoes) {
  Temp t;
  const std::string log = VIMG_TEST_DATA_DIR "/touch-latency-henze2017/FittsTasks-participant1.txt";
  const auto imported = test::run_command(kVimg + " gesture import '" + log + "' --px-per-mm 12.72 --out " + t.at("g.csv"));
  ASSERT_EQ(imported.exit_code, 0) << imported.out;
  ASSERT_GT(lines_of(t.at("g.csv")).size(), 1000u);
  const auto predicted = test::run_command(kVimg + " gesture predict " + t.at("g.csv") + " --ahead-ms 33.3 --out " + t.at("p.csv"));
  ASSERT_EQ(predicted.exit_code, 0) << predicted.out;
  EXPECT_EQ(lines_of(t.at("p.csv"))[0], "time_s,finger,x_mm,y_mm,predicted_x_mm,predicted_y_mm");
  EXPECT_GT(expect_rows_as_the_library(t.at("g.csv"), t.at("p.csv"), 0.0333, kDefaultTouchPredictionModel), 500u);
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
  // The finger enters the face (top at y = 30 mm) from outside it, already moving: the default
  // (learned) model treats a stroke's first events as a finger starting from rest, as people's
  // strokes do (docs/touch-prediction.md, "The learned model"), so a sweep that starts at full speed on a
  // primitive is not what compensation is for.
  ASSERT_EQ(test::run_command(kVimg + " gesture line --from 35,0 --to 35,60 --speed 150 --rate 60 --out " + t.at("g.csv")).exit_code, 0);
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
