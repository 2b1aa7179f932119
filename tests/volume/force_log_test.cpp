// The haptic loop's per-cycle CSV log and its run report (player/haptic/force_log.hpp,
// force_run_report.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/force_log.hpp"
#include "player/haptic/force_run_report.hpp"
#include "storage/number_text.hpp"
#include "tests/volume/test_shaders.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(VIMG_BINARY_DIR) / "test_output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!text.empty() && text.back() == sep) parts.push_back("");
  return parts;
}

double number(const std::string& text) {
  const ParsedNumber v = parse_decimal(text);
  EXPECT_TRUE(std::holds_alternative<double>(v)) << text;
  return std::holds_alternative<double>(v) ? std::get<double>(v) : 0.0;
}

TEST(ForceLog, ARowIsTimePositionInMillimetresForceAndFlagNames) {
  ForceCycleRecord r;
  r.time_s = 0.125;
  r.position_m = {0.015625, -0.001953125, 0.0};  // exact in binary, in m and in mm
  r.force_N = {0.5, -1.25, 3e-7};
  r.flags = safety_flag::clamp | safety_flag::gate | safety_flag::slew;
  EXPECT_EQ(format_force_log_row(r), "0.125,15.625,-1.953125,0,0.5,-1.25,3e-07,gate|clamp|slew\n");
  r.flags = 0;
  EXPECT_EQ(format_force_log_row(r).substr(format_force_log_row(r).size() - 2), ",\n");
}

struct LoggedRun {
  std::uint64_t cycles = 0;
  std::uint64_t dropped = 0;
  std::uint64_t written_while_running = 0;  // rows the writer had written when the loop stopped
  std::optional<std::string> error;
};

constexpr std::size_t kLogRing = 256;  // much smaller than the run: the writer must keep up

LoggedRun run_logged_loop(const fs::path& log, bool finish) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{{0.0, Vec3{}}, {1.0, Vec3{0.05, 0.0, 0.0}}});
  HapticLoopConfig c;
  c.safety.gate_force_N = 1e9;
  c.safety.stale_limit_cycles = 1000000;
  c.safety.overrun_limit_cycles = 1000000;
  c.log_capacity_rows = kLogRing;
  HapticLoop loop(sim, c);
  loop.submit_scene(std::make_unique<HapticScene>(
      DeviceProfile{}, std::vector<std::shared_ptr<const void>>{},
      std::vector<std::shared_ptr<const ForceShader>>{std::make_shared<testing::AnchorSpringShader>(Vec3{}, 100.0)},
      std::vector<std::shared_ptr<const ForceShader>>{}));
  LoggedRun run;
  ForceLogWriter writer(loop, log);
  EXPECT_TRUE(writer.ok()) << writer.error();
  writer.start();
  EXPECT_TRUE(loop.start());
  // Until the loop has run 600 cycles, over twice the ring, and the writer has drained most of them
  // (a writer that drained only at the end would never get there: the wait gives up after 30 s).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while ((loop.cycles() < 600 || writer.rows_written() + kLogRing < loop.cycles()) && loop.running() &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  loop.stop();
  run.cycles = loop.cycles();
  run.dropped = loop.log_rows_dropped();
  run.written_while_running = writer.rows_written();
  EXPECT_FALSE(fs::exists(log));  // nothing appears before the log is complete
  if (finish) run.error = writer.finish();
  return run;
}

TEST(ForceLogWriter, WritesEveryRowAtomicallyEndingWithTheZeroSentAtStop) {
  const fs::path dir = fresh_dir("force_log");
  const fs::path log = dir / "F.csv";
  const LoggedRun run = run_logged_loop(log, true);
  ASSERT_FALSE(run.error) << *run.error;
  const std::vector<std::string> lines = split(read_text(log), '\n');
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0] + "\n", kForceLogHeader);
  EXPECT_EQ(lines.back(), "");  // ends with a newline
  const std::size_t rows = lines.size() - 2;
  // Every cycle is in the log: none dropped although the ring holds less than a third of the run.
  EXPECT_EQ(run.dropped, 0u);
  EXPECT_EQ(rows, run.cycles);
  EXPECT_GE(run.cycles, 600u);
  EXPECT_GE(run.written_while_running + kLogRing, run.cycles);
  double last_time = -1.0;
  for (std::size_t i = 1; i <= rows; ++i) {
    const std::vector<std::string> fields = split(lines[i], ',');
    ASSERT_EQ(fields.size(), 8u) << lines[i];
    const double t = number(fields[0]);
    EXPECT_GT(t, last_time) << i;
    last_time = t;
    const Vec3 f{number(fields[4]), number(fields[5]), number(fields[6])};
    EXPECT_LE(norm(f), 3.3 + 1e-9);
  }
  const std::vector<std::string> last = split(lines[rows], ',');
  EXPECT_EQ(number(last[4]), 0.0);
  EXPECT_EQ(number(last[5]), 0.0);
  EXPECT_EQ(number(last[6]), 0.0);
  EXPECT_EQ(last[7], "stop");
  // Only the log is left in the folder: no temporary file.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(ForceLogWriter, AnUnfinishedLogLeavesNoFile) {
  const fs::path dir = fresh_dir("force_log_unfinished");
  run_logged_loop(dir / "F.csv", false);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
}

TEST(ForceLogWriter, AnUnwritableLogSaysWhy) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{{0.0, Vec3{}}});
  HapticLoopConfig c;
  c.log_capacity_rows = 16;
  HapticLoop loop(sim, c);
  ForceLogWriter writer(loop, "/nonexistent-folder/F.csv");
  EXPECT_FALSE(writer.ok());
  EXPECT_NE(writer.error().find("/nonexistent-folder/F.csv"), std::string::npos) << writer.error();
  EXPECT_TRUE(writer.finish().has_value());
}

TEST(ForceRunReport, JsonHasEveryFigure) {
  ForceRunReport r;
  r.target_rate_hz = 1000.0;
  r.timing.rate_hz = 999.5;
  r.timing.jitter_p50_us = 12.0;
  r.timing.jitter_p99_us = 80.0;
  r.timing.jitter_max_us = 250.0;
  r.timing.overruns = 3;
  r.timing.skips = 1;
  r.timing.cycles = 2000;
  r.timing.elapsed_s = 1.999;
  r.max_force_N = 1.5;
  r.clamp_N = 3.3;
  r.max_slew_N_per_ms = 1.0;
  r.clamp_hits = 7;
  r.log_rows_dropped = 0;
  r.exit_reason = "seconds elapsed";
  r.device = "sim";
  r.device_state = "stopped";
  r.scheduling = "normal priority (SCHED_FIFO 80 refused: \"Operation not permitted\")";
  EXPECT_EQ(force_run_report_json(r),
            "{\"rate_hz\":999.5,\"target_rate_hz\":1000,\"jitter_p50_us\":12,\"jitter_p99_us\":80,\"jitter_max_us\":250,"
            "\"overruns\":3,\"skips\":1,\"cycles\":2000,\"elapsed_s\":1.999,\"max_force_N\":1.5,\"clamp_N\":3.3,"
            "\"max_slew_N_per_ms\":1,\"clamp_hits\":7,\"log_rows_dropped\":0,\"exit_reason\":\"seconds elapsed\","
            "\"device\":\"sim\",\"device_state\":\"stopped\","
            "\"scheduling\":\"normal priority (SCHED_FIFO 80 refused: \\\"Operation not permitted\\\")\"}\n");
}

}  // namespace
}  // namespace vimg
