// The location study's parts that need no running program (apps/force/location_study_*.hpp): the
// marks file, the port that takes the mark, a trial's scene, target and row. The study's command
// line and status line are in force_args_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "storage/study/location_marks_file.hpp"
#include "apps/force/location_study_port.hpp"
#include "apps/force/location_study_trial.hpp"
#include "hal/force/hid_force_device.hpp"
#include "hal/force/hid_force_emulator.hpp"

namespace vimg::force_app {
namespace {

// --- the marks file ---

std::string first_error(const MarkTimesResult& r) { return r.diagnostics.empty() ? "" : r.diagnostics.front().to_string(); }

TEST(MarkTimes, ReadsOneTimePerTrialInOrder) {
  const MarkTimesResult r = parse_mark_times("trial,time_s\r\n# the first block\n1,0.5\n\n2,1.25\n3,600\n", "M.csv", 3);
  ASSERT_TRUE(r.ok()) << first_error(r);
  EXPECT_EQ(*r.times_s, (std::vector<double>{0.5, 1.25, 600.0}));
  EXPECT_TRUE(r.diagnostics.empty());
}

TEST(MarkTimes, NamesFileAndLineOfEveryKindOfProblem) {
  struct Case {
    const char* text;
    const char* error;
  };
  const Case cases[] = {
      {"", "M.csv: error: empty file, expected the header 'trial,time_s'"},
      {"time_s,trial\n1,1\n", "M.csv:1: error: the header must be 'trial,time_s'"},
      {"trial,time_s\n1,1\n2\n", "M.csv:3: error: expected 2 columns (trial,time_s)"},
      {"trial,time_s\n1,1,1\n", "M.csv:2: error: expected 2 columns (trial,time_s)"},
      {"trial,time_s\n1.0,1\n", "M.csv:2: error: trial '1.0' is not a whole number"},
      {"trial,time_s\n-1,1\n", "M.csv:2: error: trial '-1' is not a whole number"},
      {"trial,time_s\n1,1\n3,1\n", "M.csv:3: error: trial 3 where trial 2 comes next (one row per trial, 1 to 3 in order)"},
      {"trial,time_s\n1,1\n1,2\n", "M.csv:3: error: trial 1 where trial 2 comes next (one row per trial, 1 to 3 in order)"},
      {"trial,time_s\n1,1\n2,1\n3,1\n4,1\n", "M.csv:5: error: more rows than the study's 3 trials"},
      {"trial,time_s\n1,1\n2,1\n", "M.csv:3: error: no time for trial 3: the study has 3 trials and each needs a row"},
      {"trial,time_s\n1,0\n", "M.csv:2: error: time_s 0 is not in (0, 600] s (limit 600)"},
      {"trial,time_s\n1,-2\n", "M.csv:2: error: time_s -2 is not in (0, 600] s (limit 600)"},
      {"trial,time_s\n1,600.5\n", "M.csv:2: error: time_s 600.5 is not in (0, 600] s (limit 600)"},
      {"trial,time_s\n1,nan\n", "M.csv:2: error: time_s 'nan' "},
      {"trial,time_s\n1,\x1b[2J\n", "M.csv:2: error: time_s '\\x1B[2J' "},
  };
  for (const Case& c : cases) {
    const MarkTimesResult r = parse_mark_times(c.text, "M.csv", 3);
    EXPECT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(first_error(r).rfind(c.error, 0), 0u) << "got: " << first_error(r) << "\nwanted: " << c.error;
  }
}

TEST(MarkTimes, AFileThatIsNotThereOrNotRegularIsAnError) {
  const MarkTimesResult missing = load_mark_times("/nonexistent/M.csv", 3);
  EXPECT_FALSE(missing.ok());
  EXPECT_EQ(first_error(missing).rfind("/nonexistent/M.csv: error: ", 0), 0u) << first_error(missing);
  const MarkTimesResult device = load_mark_times("/dev/zero", 3);
  EXPECT_FALSE(device.ok());
  EXPECT_NE(first_error(device).find("not a regular file"), std::string::npos) << first_error(device);
}

// --- the port that takes the mark ---

// A device whose samples the test scripts, one per read.
class ScriptedPort final : public HapticPort {
 public:
  std::deque<ProbeSample> samples;
  std::vector<double> read_times;
  bool read(double time_s, ProbeSample& sample) override {
    read_times.push_back(time_s);
    if (samples.empty()) return false;
    sample = samples.front();
    samples.pop_front();
    return true;
  }
  bool write_force(const Vec3&) override { return true; }
  ForceDeviceLimits limits() const override { return {}; }
};

ProbeSample sample(double x_m, unsigned buttons) {
  ProbeSample s;
  s.position_m = {x_m, 0.01, -0.02};
  s.buttons = buttons;
  return s;
}

TEST(MarkingPort, MarksWhereTheProbeIsWhenButtonZeroGoesDown) {
  ScriptedPort device;
  device.samples = {sample(0.001, 0), sample(0.002, 2), sample(0.003, 1), sample(0.004, 0), sample(0.005, 1)};
  MarkingPort port(device);
  ProbeSample s;
  ASSERT_TRUE(port.read(0.001, s));
  ASSERT_TRUE(port.read(0.002, s));  // button 1 is not the mark
  EXPECT_FALSE(port.marked());
  ASSERT_TRUE(port.read(0.003, s));
  ASSERT_TRUE(port.marked());
  EXPECT_EQ(port.mark().position_m, (Vec3{0.003, 0.01, -0.02}));
  EXPECT_EQ(port.mark().time_s, 0.003);
  ASSERT_TRUE(port.read(0.004, s));
  ASSERT_TRUE(port.read(0.005, s));  // a second press does not move the mark
  EXPECT_EQ(port.mark().position_m.x, 0.003);
  EXPECT_FALSE(port.read(0.006, s));  // a failed read stays a failed read
}

TEST(MarkingPort, AButtonStillHeldFromThePreviousPressCountsOnlyAfterItsRelease) {
  ScriptedPort device;
  device.samples = {sample(0.001, 1), sample(0.002, 1), sample(0.003, 0), sample(0.004, 1)};
  MarkingPort port(device);
  ProbeSample s;
  port.read(0.001, s);
  port.read(0.002, s);
  port.read(0.003, s);
  EXPECT_FALSE(port.marked());
  port.read(0.004, s);
  ASSERT_TRUE(port.marked());
  EXPECT_EQ(port.mark().position_m.x, 0.004);
}

TEST(MarkingPort, AKeyStandsInForTheButtonAtTheNextCycle) {
  ScriptedPort device;
  device.samples = {sample(0.001, 0), sample(0.002, 0)};
  MarkingPort port(device);
  ProbeSample s;
  port.read(0.001, s);
  EXPECT_FALSE(port.marked());
  port.press();
  port.read(0.002, s);
  ASSERT_TRUE(port.marked());
  EXPECT_EQ(port.mark().position_m.x, 0.002);
  EXPECT_EQ(port.time_s(), 0.002);
}

TEST(MarkingPort, OnTheSimulatorTimeIsTheCycleCountAndTheMarkIsTheHandOnItsPath) {
  // The hand moves along x at 100 mm/s from -50 mm.
  SimulatedForceDevice sim({{0.0, {-0.05, 0.0, 0.01}}, {1.0, {0.05, 0.0, 0.01}}});
  MarkingPort port(sim, 1000.0, 0.2505);
  ProbeSample s;
  // Whatever times the loop passes (a stall, a skip), the simulator is read at n / 1000 Hz.
  for (int n = 1; n <= 250; ++n) {
    ASSERT_TRUE(port.read(n * 0.004, s));
    EXPECT_EQ(s.buttons & 1u, 0u);
  }
  EXPECT_FALSE(port.marked());
  EXPECT_EQ(port.time_s(), 0.25);
  ASSERT_TRUE(port.read(5.0, s));  // the 251st cycle: 0.251 s >= 0.2505 s
  EXPECT_EQ(s.buttons & 1u, 1u);
  ASSERT_TRUE(port.marked());
  const ProbeMark m = port.mark();
  EXPECT_EQ(m.time_s, 0.251);  // the cycle count over the rate: exactly the decimal
  EXPECT_EQ(m.position_m, sim.hand_position_m(m.time_s));
  EXPECT_NEAR(m.position_m.x, -0.05 + 0.1 * 0.251, 1e-12);
  EXPECT_EQ(m.position_m.z, 0.01);
}

TEST(MarkingPort, WithoutAScriptedPressTheSimulatedButtonStaysUp) {
  SimulatedForceDevice sim(std::vector<HandPathPoint>{{0.0, Vec3{}}});
  MarkingPort port(sim, 1000.0, std::nullopt);
  ProbeSample s;
  for (int n = 0; n < 100; ++n) port.read(0.0, s);
  EXPECT_FALSE(port.marked());
  port.press();
  port.read(0.0, s);
  EXPECT_TRUE(port.marked());
}

TEST(MarkingPort, AHidDevicesButtonZeroMarksThroughTheProtocol) {
  auto emulator = std::make_unique<HidForceEmulator>();
  HidForceEmulator& hand = *emulator;
  std::string error;
  auto device = HidForceDevice::open(std::move(emulator), error);
  ASSERT_TRUE(device) << error;
  MarkingPort port(*device);
  ProbeSample s;
  auto cycle = [&](double t, double x_m, std::uint8_t buttons) {
    hand.set_position({x_m, -0.01, 0.02});
    hand.set_buttons(buttons);
    hand.emit_state();
    return port.read(t, s);
  };
  ASSERT_TRUE(cycle(0.001, 0.010, 0b01));  // held from the press that began the trial
  ASSERT_TRUE(cycle(0.002, 0.011, 0b10));  // button 1 alone
  EXPECT_FALSE(port.marked());
  ASSERT_TRUE(cycle(0.003, 0.012, 0b11));
  ASSERT_TRUE(port.marked());
  EXPECT_NEAR(port.mark().position_m.x, 0.012, 1e-6);  // the protocol's micrometres
  EXPECT_NEAR(port.mark().position_m.z, 0.02, 1e-6);
  EXPECT_EQ(port.mark().time_s, 0.003);
}

// --- a trial's scene, target and row ---

TEST(LocationTrial, TheSceneHasGuidanceAndOnlyTheMetaphorUnderTest) {
  const StudySet set = make_study_set(11);
  const VolumeScene rough = location_trial_scene(set, LocationMetaphor::roughness);
  EXPECT_TRUE(rough.kinaesthetic && rough.kinaesthetic->mode == KinaestheticMode::vector_guidance);
  EXPECT_EQ(rough.roughness, set.scene.roughness);
  EXPECT_TRUE(rough.transition_cues.empty());
  const VolumeScene cue = location_trial_scene(set, LocationMetaphor::transition_cue);
  EXPECT_EQ(cue.kinaesthetic, set.scene.kinaesthetic);
  EXPECT_TRUE(cue.roughness.empty());
  EXPECT_EQ(cue.transition_cues, set.scene.transition_cues);
  EXPECT_EQ(rough.device, location_study_device());
}

// The vibrotactile force of a built scene along a straight stroke at 50 mm/s, 1 kHz.
std::vector<double> vibration_along(HapticScene& scene, Vec3 from_m, Vec3 to_m) {
  std::vector<double> out;
  const Vec3 velocity = (to_m - from_m) / (norm(to_m - from_m) / 0.05);
  const int steps = static_cast<int>(norm(to_m - from_m) / 0.05 * 1000.0);
  scene.begin_contact();
  Vec3 last = from_m;
  for (int n = 0; n <= steps; ++n) {
    InteractionState s;
    s.position_m = from_m + (double(n) / steps) * (to_m - from_m);
    s.previous_position_m = last;
    s.velocity_m_per_s = velocity;
    s.time_s = n * 1e-3;
    s.dt_s = n == 0 ? 0.0 : 1e-3;
    s.proxy_position_m = s.position_m;
    s.proxy_velocity_m_per_s = velocity;
    last = s.position_m;
    out.push_back(norm(scene.evaluate(s).vibrotactile_N));
  }
  return out;
}

double largest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

TEST(LocationTrial, TheBuiltScenesRenderTheirOwnMetaphorOnly) {
  const StudySet set = make_study_set(11);
  const double plane_m = set.layout.plane_z_mm * 1e-3;
  // Far from the plane (beyond the 20 mm band), along x; and across the plane, along z.
  const double far_z_m = plane_m > 0 ? plane_m - 0.03 : plane_m + 0.03;
  const Vec3 far_from{-0.06, 0.0, far_z_m}, far_to{0.06, 0.0, far_z_m};
  const Vec3 across_from{0.0, 0.0, plane_m - 0.01}, across_to{0.0, 0.0, plane_m + 0.01};
  auto rough = build_location_trial_scene(set, LocationMetaphor::roughness);
  auto cue = build_location_trial_scene(set, LocationMetaphor::transition_cue);
  EXPECT_GT(largest(vibration_along(*rough, far_from, far_to)), 0.1);  // 0.6 N roughness everywhere
  EXPECT_EQ(largest(vibration_along(*cue, far_from, far_to)), 0.0);    // no plane crossed
  EXPECT_GT(largest(vibration_along(*cue, across_from, across_to)), 0.1);  // the cue rings at the plane
  auto rest = build_resting_scene(location_study_device());
  EXPECT_EQ(largest(vibration_along(*rest, across_from, across_to)), 0.0);
}

TEST(LocationTrial, TheTargetIsTheBendsCentreOnThePlaneAndTheErrorIsInXZ) {
  LocationTrialInput in;
  in.participant = "P01";
  in.trial = 3;
  in.metaphor = LocationMetaphor::transition_cue;
  in.seed = 99;
  in.layout = study_layout(99);
  in.mark_m = {0.0123, -0.04, -0.0071};
  in.explore_s = 12.5;
  in.time_utc = "2026-11-25T16:38:51Z";
  const LocationTrial row = location_trial_row(in);
  EXPECT_EQ(row.participant, "P01");
  EXPECT_EQ(row.trial, 3);
  EXPECT_EQ(row.metaphor, LocationMetaphor::transition_cue);
  EXPECT_EQ(row.seed, 99u);
  EXPECT_EQ(row.target_x_mm, study_layout(99).bend_x_mm);
  EXPECT_EQ(row.target_z_mm, study_layout(99).plane_z_mm);
  EXPECT_DOUBLE_EQ(row.mark_x_mm, 12.3);
  EXPECT_DOUBLE_EQ(row.mark_y_mm, -40.0);
  EXPECT_DOUBLE_EQ(row.mark_z_mm, -7.1);
  // y plays no part: the target is a line along y.
  EXPECT_EQ(row.error_mm, std::hypot(row.mark_x_mm - row.target_x_mm, row.mark_z_mm - row.target_z_mm));
  in.mark_m.y = 0.05;
  EXPECT_EQ(location_trial_row(in).error_mm, row.error_mm);
  EXPECT_EQ(row.explore_s, 12.5);
  EXPECT_EQ(row.time_utc, "2026-11-25T16:38:51Z");
  // On the target itself, no error.
  in.mark_m = {in.layout.bend_x_mm * 1e-3, 0.0, in.layout.plane_z_mm * 1e-3};
  EXPECT_NEAR(location_trial_row(in).error_mm, 0.0, 1e-12);
}

}  // namespace
}  // namespace vimg::force_app
