// vimg-force --study on the simulated device when the device faults during a trial (docs/volume-location-study.md,
// "Location study", "Signals and errors"): the trial ends unrecorded with the device at rest and runs
// again from its start, so the trial file holds every trial once; a device that faults on every
// attempt ends the study after three faults in a row (exit 1, the finished trials kept, the next run
// continuing). The fault is injected on the trial's own clock (--sim-fault: a read of the simulated
// device fails 0.1 s into the attempt), never by the wall clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/force_app/location_study_program.hpp"

namespace vimg {
namespace {

using namespace location_study_test;

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
  return n;
}

class LocationStudyFault : public LocationStudyProgram {
 protected:
  std::vector<std::string> faulting(const std::string& participant, const fs::path& marks, const std::string& fault) const {
    std::vector<std::string> args = study_args(participant, marks);
    args.insert(args.end(), {"--sim-fault", fault});
    return args;
  }
};

TEST_F(LocationStudyFault, AFaultedTrialIsRedoneAndEveryTrialIsRecordedOnce) {
  const fs::path marks = marks_file("quick.csv", 14, 0.3, 0.3);
  const Exit e = run(faulting("P11", marks, "3:2"), root_);  // trial 3 faults twice, then goes through
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(count_of(e.err, "vimg-force: device fault in trial 3: redoing it"), 2u) << e.err;
  EXPECT_EQ(count_of(e.err, "device fault"), 2u) << e.err;
  EXPECT_NE(e.err.find("device read failed"), std::string::npos) << e.err;
  // Three attempts began (their first status lines); one was marked.
  EXPECT_EQ(count_of(e.err, "\ntrial 3 of 14  "), 4u) << e.err;  // three starts and the mark
  EXPECT_EQ(count_of(e.err, "\ntrial 2 of 14  "), 2u) << e.err;  // its start and its mark
  EXPECT_NE(e.err.find("has finished all 14 trials"), std::string::npos) << e.err;
  const std::vector<LocationTrial> rows = trials_in(csv("P11"));
  ASSERT_EQ(rows.size(), 14u);  // trials 1..14, none twice, none missing
  expect_planned(rows, "P11");
  // The redo began afresh: the hand from its path's start and the trial's clock from zero, so the
  // press at 0.3 s marks where it marks in every other trial.
  for (std::size_t i = 0; i < 14; ++i) {
    EXPECT_EQ(rows[i].explore_s, 0.3) << "trial " << i + 1;
    EXPECT_EQ(rows[i].mark_x_mm, rows[0].mark_x_mm) << "trial " << i + 1;
    EXPECT_EQ(rows[i].mark_y_mm, rows[0].mark_y_mm) << "trial " << i + 1;
    EXPECT_EQ(rows[i].mark_z_mm, rows[0].mark_z_mm) << "trial " << i + 1;
  }
}

TEST_F(LocationStudyFault, ADeviceThatFaultsOnEveryAttemptEndsTheStudyAfterThreeInARow) {
  const fs::path marks = marks_file("quick.csv", 14, 0.3, 0.3);
  const Exit e = run(faulting("P12", marks, "3:1000"), root_);
  EXPECT_EQ(e.code, 1) << e.err;
  EXPECT_EQ(count_of(e.err, "vimg-force: device fault in trial 3: redoing it"), 2u) << e.err;
  EXPECT_NE(e.err.find("vimg-force: error: device fault in trial 3, 3 in a row: the study stops with the device at "
                       "rest; 2 trials are in "),
            std::string::npos)
      << e.err;
  EXPECT_NE(e.err.find("the next run continues at trial 3"), std::string::npos) << e.err;
  EXPECT_EQ(count_of(e.err, "device fault"), 3u) << e.err;
  EXPECT_EQ(count_of(e.err, "\ntrial 3 of 14  "), 3u) << e.err;  // three starts, no mark
  const std::string text = read_text(csv("P12"));
  std::vector<LocationTrial> rows = trials_in(csv("P12"));
  ASSERT_EQ(rows.size(), 2u);
  expect_planned(rows, "P12");

  // The next run, on a device that works, continues at trial 3 and finishes with every trial once.
  const Exit rerun = run(study_args("P12", marks), root_, "rerun");
  ASSERT_EQ(rerun.code, 0) << rerun.err;
  EXPECT_NE(rerun.err.find("continues at trial 3 of 14"), std::string::npos) << rerun.err;
  EXPECT_EQ(read_text(csv("P12")).substr(0, text.size()), text);
  rows = trials_in(csv("P12"));
  ASSERT_EQ(rows.size(), 14u);
  expect_planned(rows, "P12");
}

TEST_F(LocationStudyFault, AFaultNeedsTheSimulatedDeviceAndAWellFormedTrial) {
  std::vector<std::string> hid = faulting("P13", kExample / "marks.csv", "3:1");
  for (std::size_t i = 0; i + 1 < hid.size(); ++i) {
    if (hid[i] == "--device") hid[i + 1] = "hid";
  }
  hid.erase(std::find(hid.begin(), hid.end(), "--path"), std::find(hid.begin(), hid.end(), "--realtime-priority"));
  const Exit h = run(hid, root_, "hid");
  EXPECT_EQ(h.code, 2) << h.err;
  EXPECT_NE(h.err.find("--sim-fault needs --device sim"), std::string::npos) << h.err;
  for (const char* bad : {"3", "0:1", "3:0", "x:1", "3:1:1"}) {
    const Exit b = run(faulting("P13", kExample / "marks.csv", bad), root_, "bad");
    EXPECT_EQ(b.code, 2) << bad << ": " << b.err;
  }
  EXPECT_TRUE(files_in(results()).empty());
}

}  // namespace
}  // namespace vimg
