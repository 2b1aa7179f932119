// vimg-force's command line (apps/force/force_args.hpp): the project's conventions, and its own
// rules (a device is required, --path only with the simulated device); the location study's options
// and status line (apps/force/status_line.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "apps/force/force_args.hpp"
#include "apps/force/status_line.hpp"

namespace vimg::force_app {
namespace {

ForceArgsResult parse(std::vector<const char*> args) {
  args.insert(args.begin(), "vimg-force");
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  ForceArgsResult r = parse_force_args(static_cast<int>(args.size()), args.data());
  testing::internal::GetCapturedStdout();
  testing::internal::GetCapturedStderr();
  return r;
}

TEST(ForceArgs, ReadsEveryOption) {
  const ForceArgsResult r = parse({"s.vscene.xml", "--device", "sim", "--path", "p.csv", "--seconds", "2.5", "--log",
                                   "f.csv", "--telemetry", "t.json", "--realtime-priority", "0"});
  ASSERT_TRUE(r.args);
  EXPECT_EQ(r.args->scene_path, "s.vscene.xml");
  EXPECT_TRUE(r.args->is_sim());
  EXPECT_EQ(r.args->path_file, "p.csv");
  EXPECT_EQ(r.args->seconds, 2.5);
  EXPECT_EQ(r.args->log_file, "f.csv");
  EXPECT_EQ(r.args->telemetry_file, "t.json");
  EXPECT_EQ(r.args->realtime_priority, 0);
}

TEST(ForceArgs, DefaultsRunUntilASignalWithSchedFifo) {
  const ForceArgsResult r = parse({"s.vscene.xml", "--device", "hid"});
  ASSERT_TRUE(r.args);
  EXPECT_FALSE(r.args->seconds);
  EXPECT_EQ(r.args->realtime_priority, 80);
  EXPECT_EQ(r.args->hid_path, "");
  const ForceArgsResult path = parse({"s.vscene.xml", "--device", "hid:/dev/hidraw3"});
  ASSERT_TRUE(path.args);
  EXPECT_FALSE(path.args->is_sim());
  EXPECT_EQ(path.args->hid_path, "/dev/hidraw3");
}

TEST(ForceArgs, HelpAndVersionExitZero) {
  EXPECT_EQ(parse({"--help"}).exit_code, 0);
  EXPECT_FALSE(parse({"--help"}).args);
  EXPECT_EQ(parse({"--version"}).exit_code, 0);
}

TEST(ForceArgs, UsageErrorsExitTwo) {
  const std::vector<std::vector<const char*>> bad = {
      {},                                                        // no scene
      {"s.vscene.xml"},                                          // no device
      {"s.vscene.xml", "--device", "usb"},                       // not sim, hid or hid:PATH
      {"s.vscene.xml", "--device", "hid:"},                      // an empty path
      {"s.vscene.xml", "--device", "hid", "--path", "p.csv"},    // a real device is moved by hand
      {"s.vscene.xml", "--device", "sim", "--seconds", "nan"},
      {"s.vscene.xml", "--device", "sim", "--seconds", "0"},
      {"s.vscene.xml", "--device", "sim", "--seconds", "-1"},
      {"s.vscene.xml", "--device", "sim", "--realtime-priority", "100"},
      {"s.vscene.xml", "--device", "sim", "--frobnicate"},
      {"a.vscene.xml", "b.vscene.xml", "--device", "sim"},
  };
  for (const auto& args : bad) {
    const ForceArgsResult r = parse(args);
    EXPECT_FALSE(r.args);
    EXPECT_EQ(r.exit_code, 2) << (args.empty() ? "" : args.back());
  }
}

TEST(StatusLine, ShowsRateJitterOverrunsForceAndState) {
  HapticLoopStatus s;
  s.state = LoopState::running;
  s.timing.rate_hz = 999.96;
  s.timing.jitter_p99_us = 45.4;
  s.timing.overruns = 3;
  s.max_force_N = 1.234;
  EXPECT_EQ(format_status_line(s), "1000.0 Hz  jitter p99 45 us  3 overruns  max |F| 1.23 N  running");
  s.state = LoopState::faulted;
  EXPECT_EQ(format_status_line(s).substr(format_status_line(s).size() - 5), "fault");
}

// --- the location study ---

TEST(LocationStudyArgs, ReadsTheStudyOptions) {
  const ForceArgsResult r = parse({"--study", "s.xml", "--participant", "P-01_a", "--results", "out", "--device", "sim",
                                   "--path", "p.csv", "--marks", "m.csv", "--restart", "--realtime-priority", "0"});
  ASSERT_TRUE(r.args);
  EXPECT_TRUE(r.args->is_study());
  EXPECT_EQ(r.args->study_file, "s.xml");
  EXPECT_EQ(r.args->participant, "P-01_a");
  EXPECT_EQ(r.args->results_dir, "out");
  EXPECT_EQ(r.args->path_file, "p.csv");
  EXPECT_EQ(r.args->marks_file, "m.csv");
  EXPECT_TRUE(r.args->restart);
  const ForceArgsResult hid = parse({"--study", "s.xml", "--participant", "P1", "--results", "out", "--device", "hid"});
  ASSERT_TRUE(hid.args);
  EXPECT_FALSE(hid.args->restart);
  EXPECT_FALSE(hid.args->is_sim());
  EXPECT_FALSE(parse({"s.vscene.xml", "--device", "sim"}).args->is_study());
}

TEST(LocationStudyArgs, UsageErrorsExitTwo) {
  const std::vector<std::vector<const char*>> bad = {
      {"--study", "s.xml", "--results", "out", "--device", "sim"},                              // no participant
      {"--study", "s.xml", "--participant", "P1", "--device", "sim"},                            // no results
      {"--study", "s.xml", "--participant", "P 1", "--results", "out", "--device", "sim"},      // not an ID
      {"--study", "s.xml", "--participant", "../P1", "--results", "out", "--device", "sim"},    // not an ID
      {"--study", "s.xml", "--participant", "", "--results", "out", "--device", "sim"},         // not an ID
      {"s.vscene.xml", "--study", "s.xml", "--participant", "P1", "--results", "o", "--device", "sim"},  // both
      {"--study", "s.xml", "--participant", "P1", "--results", "o", "--device", "hid", "--marks", "m.csv"},
      {"--study", "s.xml", "--participant", "P1", "--results", "o", "--device", "sim", "--seconds", "2"},
      {"--study", "s.xml", "--participant", "P1", "--results", "o", "--device", "sim", "--log", "f.csv"},
      {"--study", "s.xml", "--participant", "P1", "--results", "o", "--device", "sim", "--telemetry", "t.json"},
      {"--study", "s.xml", "--participant", "P1", "--results", "o"},                             // no device
      {"s.vscene.xml", "--device", "sim", "--participant", "P1"},                                // needs --study
      {"s.vscene.xml", "--device", "sim", "--restart"},
      {"s.vscene.xml", "--device", "sim", "--marks", "m.csv"},
      {"--device", "sim"},                                                                       // neither
  };
  for (const auto& args : bad) {
    const ForceArgsResult r = parse(args);
    EXPECT_FALSE(r.args) << args[1] << " " << args.back();
    EXPECT_EQ(r.exit_code, 2) << args[1] << " " << args.back();
  }
  std::string long_id(65, 'a');
  EXPECT_FALSE(parse({"--study", "s.xml", "--participant", long_id.c_str(), "--results", "o", "--device", "sim"}).args);
  long_id.pop_back();
  EXPECT_TRUE(parse({"--study", "s.xml", "--participant", long_id.c_str(), "--results", "o", "--device", "sim"}).args);
}

TEST(LocationStudyStatus, SaysTrialMetaphorAndWholeSecondsOnly) {
  EXPECT_EQ(format_trial_status(3, 14, LocationMetaphor::roughness, 12.9), "trial 3 of 14  roughness  elapsed 12 s");
  EXPECT_EQ(format_trial_status(14, 14, LocationMetaphor::transition_cue, 0.2), "trial 14 of 14  transition cue  elapsed 0 s");
  EXPECT_EQ(format_trial_status(1, 2, LocationMetaphor::transition_cue, NAN), "trial 1 of 2  transition cue  elapsed 0 s");
}

}  // namespace
}  // namespace vimg::force_app
