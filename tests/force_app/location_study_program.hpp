#pragma once
// What the tests of vimg-force --study share: the shipped example, its plan, the rows a run must
// leave (each the plan's trial, once, in order), and a fixture that runs the example on the
// simulated device in a folder of the test's own.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "primitives/volume/study_set.hpp"
#include "storage/number_text.hpp"
#include "storage/study/study_file.hpp"
#include "storage/study/trial_table.hpp"
#include "study/trial_plan.hpp"
#include "tests/force_app/location_study_process.hpp"

namespace vimg::location_study_test {

inline const fs::path kExample = fs::path(VIMG_SOURCE_DIR) / "assets" / "examples" / "location";

inline std::vector<LocationTrial> trials_in(const fs::path& csv) {
  const TrialTableResult<LocationTrial> table = read_location_trials(csv);
  EXPECT_TRUE(table.ok()) << (table.diagnostics.empty() ? "" : table.diagnostics.front().to_string());
  return table.rows;
}

inline std::vector<study::LocationTrialPlan> example_plan(const std::string& participant) {
  const StudyFileResult<LocationStudy> study = load_location_study(kExample / "study.xml");
  EXPECT_TRUE(study.ok());
  return study.ok() ? study::plan_location_trials(*study.study, participant) : std::vector<study::LocationTrialPlan>{};
}

// Rows 1..n in order, each the plan's trial: its metaphor, its seed and the target that seed makes.
inline void expect_planned(const std::vector<LocationTrial>& rows, const std::string& participant) {
  const auto plan = example_plan(participant);
  ASSERT_GE(plan.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const LocationTrial& r = rows[i];
    EXPECT_EQ(r.participant, participant);
    EXPECT_EQ(r.trial, static_cast<int>(i + 1));
    EXPECT_EQ(r.metaphor, plan[i].metaphor) << "trial " << i + 1;
    EXPECT_EQ(r.seed, plan[i].data_seed) << "trial " << i + 1;
    const StudyLayout layout = study_layout(r.seed);
    EXPECT_EQ(r.target_x_mm, layout.bend_x_mm) << "trial " << i + 1;
    EXPECT_EQ(r.target_z_mm, layout.plane_z_mm) << "trial " << i + 1;
    EXPECT_EQ(r.error_mm, std::hypot(r.mark_x_mm - r.target_x_mm, r.mark_z_mm - r.target_z_mm)) << "trial " << i + 1;
    EXPECT_EQ(r.time_utc.size(), 20u);
    EXPECT_EQ(r.time_utc.substr(10, 1) + r.time_utc.substr(19), "TZ") << r.time_utc;
  }
}

class LocationStudyProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(VIMG_BINARY_DIR) / "test_output" / "force_app_location" /
            ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(root_);
    fs::create_directories(root_ / "results");
  }
  fs::path results() const { return root_ / "results"; }
  fs::path csv(const std::string& participant) const { return results() / (participant + ".location.csv"); }
  // The example study on the simulated device, with the example's hand path and `marks`.
  std::vector<std::string> study_args(const std::string& participant, const fs::path& marks) const {
    return {"--study", (kExample / "study.xml").string(), "--participant", participant, "--results", results().string(),
            "--device", "sim", "--path", (kExample / "hand_path.csv").string(), "--marks", marks.string(),
            "--realtime-priority", "0"};
  }
  // A marks file for 14 trials: trials 1..fast at `fast_s`, the rest at `slow_s`.
  fs::path marks_file(const std::string& name, std::size_t fast, double fast_s, double slow_s) const {
    std::ofstream out(root_ / name);
    out << "trial,time_s\n";
    for (std::size_t k = 1; k <= 14; ++k) out << k << "," << format_decimal(k <= fast ? fast_s : slow_s) << "\n";
    return root_ / name;
  }
  fs::path root_;
};

}  // namespace vimg::location_study_test
