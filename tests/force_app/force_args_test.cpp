// vimg-force's command line (apps/force/force_args.hpp): the project's conventions, and its own
// rules (a device is required, --path only with the simulated device).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace vimg::force_app
