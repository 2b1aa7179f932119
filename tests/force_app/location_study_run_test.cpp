// vimg-force --study, the program itself on the simulated device (docs/volume-location-study.md, "Location
// study"): the shipped example end to end (14 rows whose targets follow from the seeds, marks at the
// hand's place at the scripted times, exact errors, nothing on the terminal that gives the target,
// the error or the mark away), SIGKILL in the middle and a rerun that continues, a finished
// participant refused and restarted, SIGTERM and SIGINT between marks, no HID device, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "storage/volume/probe_path_io.hpp"
#include "tests/force_app/location_study_program.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;
using namespace location_study_test;

constexpr double kPeriodS = 1e-3;  // the study's loop rate is 1 kHz

// The hand's path (mm) at time t, linearly interpolated and held at its ends, as the simulator moves it.
struct HandPath {
  std::vector<ProbePathPoint> points;
  Vec3 at_mm(double t) const {
    if (t <= points.front().time_s) return points.front().position_m * 1e3;
    if (t >= points.back().time_s) return points.back().position_m * 1e3;
    std::size_t i = 1;
    while (points[i].time_s < t) ++i;
    const ProbePathPoint &a = points[i - 1], &b = points[i];
    const double u = (t - a.time_s) / (b.time_s - a.time_s);
    return (a.position_m + u * (b.position_m - a.position_m)) * 1e3;
  }
  double max_speed_mm_per_s() const {
    double v = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      v = std::max(v, norm(points[i].position_m - points[i - 1].position_m) * 1e3 /
                          (points[i].time_s - points[i - 1].time_s));
    }
    return v;
  }
};

HandPath example_path() {
  const ProbePathParseResult parsed = parse_probe_path_csv(read_text(kExample / "hand_path.csv"), "hand_path.csv");
  EXPECT_TRUE(parsed.path.has_value());
  return HandPath{parsed.path.value_or(std::vector<ProbePathPoint>{{0.0, {}}})};
}

// trial,time_s rows, read here without the program's reader.
std::vector<double> example_marks() {
  std::vector<double> times;
  std::istringstream in(read_text(kExample / "marks.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "trial,time_s");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    EXPECT_EQ(line.substr(0, line.find(',')), std::to_string(times.size() + 1));
    times.push_back(std::get<double>(parse_decimal(line.substr(line.find(',') + 1))));
  }
  return times;
}

// "trial N of TOTAL  METAPHOR  elapsed S s", with "  marked" at the mark: nothing else.
bool is_trial_status(std::string line, std::size_t total) {
  auto take = [&](const std::string& prefix) {
    if (line.rfind(prefix, 0) != 0) return false;
    line.erase(0, prefix.size());
    return true;
  };
  auto digits = [&] {
    const std::size_t n = line.find_first_not_of("0123456789");
    if (n == 0 || n == std::string::npos) return false;
    line.erase(0, n);
    return true;
  };
  if (!take("trial ") || !digits() || !take(" of " + std::to_string(total) + "  ")) return false;
  if (!take("roughness  elapsed ") && !take("transition cue  elapsed ")) return false;
  if (!digits() || !take(" s")) return false;
  return line.empty() || line == "  marked";
}

// Every number in the program's messages ("vimg-force: ..." lines), the files it names removed
// first: each run of digits, signs, points and exponents that reads as a decimal.
std::vector<double> numbers_shown(const std::string& err, const std::vector<std::string>& folders) {
  std::vector<double> numbers;
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("vimg-force: ", 0) != 0) continue;
    for (const std::string& folder : folders) {
      for (std::size_t at; (at = line.find(folder)) != std::string::npos;) {
        const std::size_t end = line.find_first_of(" ,:", at);
        line.erase(at, end == std::string::npos ? std::string::npos : end - at);
      }
    }
    const auto in_number = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e'; };
    for (std::size_t i = 0; i < line.size();) {
      if (!in_number(line[i])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < line.size() && in_number(line[j])) ++j;
      std::string token = line.substr(i, j - i);
      while (!token.empty() && (token.back() == '.' || token.back() == '-')) token.pop_back();  // "trials." "N/ms."
      const ParsedNumber parsed = parse_decimal(token);
      if (const double* v = std::get_if<double>(&parsed)) numbers.push_back(*v);
      i = j;
    }
  }
  return numbers;
}

class LocationStudyRun : public LocationStudyProgram {};

TEST_F(LocationStudyRun, TheExampleRunsEndToEndOnTheSimulatedDevice) {
  const Exit e = run(study_args("P01", kExample / "marks.csv"), root_);
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(files_in(results()), (std::vector<std::string>{"P01.location.csv"}));
  const std::vector<LocationTrial> rows = trials_in(csv("P01"));
  ASSERT_EQ(rows.size(), 14u);
  expect_planned(rows, "P01");
  // Blocked: seven of one metaphor, then seven of the other.
  for (std::size_t i = 0; i < 14; ++i) EXPECT_EQ(rows[i].metaphor, rows[i < 7 ? 0 : 7].metaphor) << i;
  EXPECT_NE(rows[0].metaphor, rows[7].metaphor);
  // Every trial a new data set.
  for (std::size_t i = 1; i < 14; ++i) EXPECT_NE(rows[i].seed, rows[i - 1].seed);
  // The mark is the hand on its path at the first loop cycle at or after the scripted press.
  const HandPath path = example_path();
  const std::vector<double> marks = example_marks();
  ASSERT_EQ(marks.size(), 14u);
  for (std::size_t i = 0; i < 14; ++i) {
    const LocationTrial& r = rows[i];
    EXPECT_GE(r.explore_s, marks[i] - 1e-12) << "trial " << i + 1;
    EXPECT_LT(r.explore_s, marks[i] + kPeriodS + 1e-9) << "trial " << i + 1;
    const Vec3 mark{r.mark_x_mm, r.mark_y_mm, r.mark_z_mm};
    EXPECT_LT(norm(mark - path.at_mm(r.explore_s)), 1e-9) << "trial " << i + 1;
    EXPECT_LE(norm(mark - path.at_mm(marks[i])), path.max_speed_mm_per_s() * kPeriodS + 1e-9) << "trial " << i + 1;
  }
  // The terminal saw every trial, never a target or a mark.
  EXPECT_NE(e.err.find("trial 1 of 14  "), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("trial 14 of 14  "), std::string::npos) << e.err;
  EXPECT_NE(e.err.find("has finished all 14 trials"), std::string::npos) << e.err;
  for (const LocationTrial& r : rows) {
    for (double v : {r.target_x_mm, r.target_z_mm, r.error_mm}) {
      EXPECT_EQ(e.err.find(format_decimal(v)), std::string::npos) << format_decimal(v) << " shown in:\n" << e.err;
    }
  }
  // Nor the mark, in mm or in m, in any number the program printed (the status lines are checked
  // below to hold nothing but the trial, the metaphor and whole seconds).
  const std::vector<double> shown = numbers_shown(e.err, {root_.string(), kExample.string()});
  std::string leaks;
  for (const LocationTrial& r : rows) {
    for (double mm : {r.mark_x_mm, r.mark_y_mm, r.mark_z_mm}) {
      for (double v : shown) {
        if (std::abs(v - mm) <= 0.05 || std::abs(v - mm * 1e-3) <= 0.05e-3) {
          leaks += "trial " + std::to_string(r.trial) + "'s mark " + format_decimal(mm) + " mm shown as " + format_decimal(v) + "\n";
        }
      }
    }
  }
  EXPECT_EQ(leaks, "") << "in:\n" << e.err;
  std::istringstream lines(e.err);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_TRUE(line.rfind("vimg-force: ", 0) == 0 || is_trial_status(line, 14)) << line;
  }
}

TEST_F(LocationStudyRun, SigkillLosesAtMostTheTrialUnderWayAndARerunContinues) {
  const fs::path marks = marks_file("quick.csv", 14, 0.3, 0.3);
  const Child first = spawn(study_args("P02", marks), root_, "first");
  ASSERT_TRUE(wait_for_rows(first, csv("P02"), 4)) << read_text(first.err);
  ASSERT_TRUE(test::signal_child(first.pid, SIGKILL));
  const Exit killed = wait_for(first);
  ASSERT_EQ(killed.code, 128 + SIGKILL) << killed.err;
  const std::string before = read_text(csv("P02"));
  const std::size_t done = complete_rows(csv("P02"));
  ASSERT_GE(done, 4u);
  ASSERT_LT(done, 14u) << "the study ended before the kill";
  ASSERT_EQ(before.back(), '\n');

  const Exit rerun = run(study_args("P02", marks), root_, "rerun");
  ASSERT_EQ(rerun.code, 0) << rerun.err;
  EXPECT_NE(rerun.err.find("continues at trial " + std::to_string(done + 1) + " of 14"), std::string::npos) << rerun.err;
  const std::string after = read_text(csv("P02"));
  EXPECT_EQ(after.substr(0, before.size()), before);  // the rows written before the kill, untouched
  const std::vector<LocationTrial> rows = trials_in(csv("P02"));
  ASSERT_EQ(rows.size(), 14u);  // trials 1..14, none repeated, none missing
  expect_planned(rows, "P02");

  // A finished participant is refused; --restart keeps the file aside and runs the study again.
  const Exit again = run(study_args("P02", marks), root_, "again");
  EXPECT_EQ(again.code, 1);
  EXPECT_NE(again.err.find("participant P02 has finished all 14 trials"), std::string::npos) << again.err;
  EXPECT_EQ(read_text(csv("P02")), after);
  std::vector<std::string> restart_args = study_args("P02", marks);
  restart_args.push_back("--restart");
  const Exit restarted = run(restart_args, root_, "restart");
  ASSERT_EQ(restarted.code, 0) << restarted.err;
  const std::vector<std::string> files = files_in(results());
  ASSERT_EQ(files.size(), 2u);
  const std::string aside = files[0] == "P02.location.csv" ? files[1] : files[0];
  EXPECT_EQ(read_text(results() / aside), after);
  EXPECT_EQ(trials_in(csv("P02")).size(), 14u);
}

TEST_F(LocationStudyRun, SigtermAndSigintStopBetweenMarksWithTheFileIntact) {
  // Two quick trials, then trials that would last a minute: the signal comes during trial 3.
  const fs::path marks = marks_file("slow.csv", 2, 0.3, 60.0);
  const Child term = spawn(study_args("P03", marks), root_, "term");
  ASSERT_TRUE(wait_for_rows(term, csv("P03"), 2)) << read_text(term.err);
  const auto signalled = std::chrono::steady_clock::now();
  ASSERT_TRUE(test::signal_child(term.pid, SIGTERM));
  const Exit termed = wait_for(term, signalled);
  EXPECT_EQ(termed.code, 143) << termed.err;
  // Handled, not merely killed: the loop was stopped (zero force) and the program says where it stands.
  EXPECT_NE(termed.err.find("vimg-force: SIGTERM: the device is at rest; 2 trials are in "), std::string::npos) << termed.err;
  // No bound on how long that took: the message above says the signal was handled, not waited out
  // (the trial would have lasted a minute), and wait_for bounds a hang.
  const std::string text = read_text(csv("P03"));
  EXPECT_EQ(text.back(), '\n');
  std::vector<LocationTrial> rows = trials_in(csv("P03"));
  ASSERT_EQ(rows.size(), 2u);
  expect_planned(rows, "P03");
  EXPECT_EQ(files_in(results()), (std::vector<std::string>{"P03.location.csv"}));

  // The next run continues at trial 3; SIGINT there: 130, still two rows.
  const Child interrupt = spawn(study_args("P03", marks), root_, "int");
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  // The trial under way: its first status line (not "continues at trial 3 of 14").
  while (read_text(interrupt.err).find("\ntrial 3 of 14  ") == std::string::npos && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const bool in_trial_3 = read_text(interrupt.err).find("\ntrial 3 of 14  ") != std::string::npos;
  ASSERT_TRUE(test::signal_child(interrupt.pid, in_trial_3 ? SIGINT : SIGKILL));
  ASSERT_TRUE(in_trial_3) << "trial 3 never started: " << read_text(interrupt.err);
  const Exit interrupted = wait_for(interrupt);
  EXPECT_EQ(interrupted.code, 130) << interrupted.err;
  EXPECT_NE(interrupted.err.find("vimg-force: SIGINT: the device is at rest; 2 trials are in "), std::string::npos)
      << interrupted.err;
  EXPECT_NE(interrupted.err.find("the next run continues at trial 3"), std::string::npos) << interrupted.err;
  EXPECT_NE(interrupted.err.find("continues at trial 3 of 14"), std::string::npos) << interrupted.err;
  EXPECT_EQ(interrupted.err.find("marked"), std::string::npos) << interrupted.err;
  EXPECT_EQ(read_text(csv("P03")), text);
}

TEST_F(LocationStudyRun, AHidDeviceThatIsNotThereExitsOneAndWritesNothing) {
  const std::vector<std::string> study{"--study", (kExample / "study.xml").string(), "--participant", "P04", "--results",
                                       results().string()};
  std::vector<std::string> any = study;
  any.insert(any.end(), {"--device", "hid"});
  const Exit e = run(any, root_);
  EXPECT_EQ(e.code, 1) << e.err;
  EXPECT_EQ(e.err.rfind("vimg-force: error: no HID device", 0), 0u) << e.err;
  std::vector<std::string> named = study;
  named.insert(named.end(), {"--device", "hid:/dev/hidraw-none"});
  const Exit n = run(named, root_);
  EXPECT_EQ(n.code, 1);
  EXPECT_NE(n.err.find("/dev/hidraw-none: cannot open /dev/hidraw-none"), std::string::npos) << n.err;
  EXPECT_TRUE(files_in(results()).empty());
}

TEST_F(LocationStudyRun, BadInputExitsOneNamingFileAndLine) {
  std::ofstream(root_ / "bad_marks.csv") << "trial,time_s\n1,0.5\n3,0.5\n";
  const Exit marks = run(study_args("P05", root_ / "bad_marks.csv"), root_);
  EXPECT_EQ(marks.code, 1);
  EXPECT_EQ(marks.err.rfind((root_ / "bad_marks.csv").string() + ":3: error: trial 3 where trial 2 comes next", 0), 0u) << marks.err;

  std::ofstream(root_ / "bad.xml") << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<locationStudy version=\"1\" seed=\"7\">\n"
                                      "  <metaphor name=\"smoothness\"/>\n</locationStudy>\n";
  std::vector<std::string> bad_study = study_args("P05", kExample / "marks.csv");
  bad_study[1] = "bad.xml";
  const Exit study = run(bad_study, root_);
  EXPECT_EQ(study.code, 1);
  EXPECT_EQ(study.err.rfind("bad.xml:3: error: ", 0), 0u) << study.err;

  std::vector<std::string> no_folder = study_args("P05", kExample / "marks.csv");
  no_folder[5] = (root_ / "missing").string();
  const Exit folder = run(no_folder, root_);
  EXPECT_EQ(folder.code, 1) << folder.err;
  EXPECT_NE(folder.err.find("error"), std::string::npos);
  EXPECT_FALSE(fs::exists(root_ / "missing"));

  // The simulated participant cannot mark without --marks when nobody is at a terminal.
  std::vector<std::string> unmarked = study_args("P05", kExample / "marks.csv");
  unmarked.resize(unmarked.size() - 4);
  unmarked.insert(unmarked.end(), {"--realtime-priority", "0"});
  const Exit nobody = run(unmarked, root_);
  EXPECT_EQ(nobody.code, 2) << nobody.err;
  EXPECT_NE(nobody.err.find("nobody can mark"), std::string::npos) << nobody.err;
  EXPECT_TRUE(files_in(results()).empty());
}

}  // namespace
}  // namespace vimg
