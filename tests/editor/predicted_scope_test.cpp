// The scope's predicted acceleration is the actuator model run over exactly the drive the tap saw.
#include "editor/core/predicted_scope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../actuator/model_params.hpp"
#include "../actuator/test_drive.hpp"
#include "player/drive_sinks.hpp"

namespace vimg::editor {
namespace {

constexpr double kRate = 8000.0;

using test::lra;

std::vector<float> drive_signal(std::size_t n) { return test::two_tone_drive(n, kRate, 700); }

// A tap over memory, open at kRate, and a scope of `params` following it.
struct Rig {
  explicit Rig(const ResponseParams& params) {
    tap.open(kRate);
    scope.set_response(params, 1);
  }
  MemorySink memory;
  DriveTap tap{memory};
  PredictedScope scope;
};

// Writes `drive` to the tap in blocks of 64, updating the scope every `every` blocks.
void play(DriveTap& tap, PredictedScope& scope, const std::vector<float>& drive, std::size_t every) {
  for (std::size_t b = 0; b * 64 < drive.size(); ++b) {
    tap.write(std::span<const float>(drive).subspan(b * 64, std::min<std::size_t>(64, drive.size() - b * 64)),
              static_cast<double>(b * 64) / kRate);
    if ((b + 1) % every == 0) scope.update(tap);
  }
  scope.update(tap);
}

TEST(PredictedScope, AccelerationIsTheModelOfTheTappedDrive) {
  for (const std::size_t every : {1u, 3u, 40u}) {
    Rig rig(lra());
    DriveTap& tap = rig.tap;
    PredictedScope& scope = rig.scope;
    const std::vector<float> drive = drive_signal(3000);
    play(tap, scope, drive, every);
    EXPECT_EQ(scope.modelled(), drive.size());
    EXPECT_EQ(scope.skipped(), 0u);

    ActuatorModel offline(lra(), kRate);
    std::vector<float> expected(drive.size());
    for (std::size_t i = 0; i < drive.size(); ++i) expected[i] = static_cast<float>(offline.process(drive[i]));

    std::vector<float> d, a;
    scope.recent(drive.size(), d, a);
    ASSERT_EQ(a.size(), drive.size());
    for (std::size_t i = 0; i < drive.size(); ++i) {
      ASSERT_EQ(d[i], drive[i]) << i;
      ASSERT_EQ(a[i], expected[i]) << "sample " << i << ", update every " << every << " blocks";
    }
    // The resonator shapes it: the acceleration is not the drive.
    double diff = 0;
    for (std::size_t i = 0; i < drive.size(); ++i) diff += std::abs(a[i] - drive[i]);
    EXPECT_GT(diff, 10.0);
  }
}

TEST(PredictedScope, TheIdealProfileGivesTheDriveItself) {
  Rig rig(ResponseParams{});
  DriveTap& tap = rig.tap;
  PredictedScope& scope = rig.scope;
  const std::vector<float> drive = drive_signal(1000);
  play(tap, scope, drive, 2);
  std::vector<float> d, a;
  scope.recent(500, d, a);
  EXPECT_EQ(d, a);
  EXPECT_EQ(d, std::vector<float>(drive.end() - 500, drive.end()));
}

TEST(PredictedScope, ZeroPaddedWhileFewSamplesWereSeenAndAProfileChangeStartsTheModelAnew) {
  Rig rig(lra());
  DriveTap& tap = rig.tap;
  PredictedScope& scope = rig.scope;
  const std::vector<float> drive = drive_signal(128);
  play(tap, scope, drive, 1);
  std::vector<float> d, a;
  scope.recent(200, d, a);
  for (std::size_t i = 0; i < 72; ++i) EXPECT_EQ(d[i], 0.0f);
  EXPECT_EQ(d[72], drive[0]);
  // A new profile: the samples from now on go through a fresh model of it.
  scope.set_response(ResponseParams{}, 2);
  const std::vector<float> more(64, 0.25f);
  tap.write(more, 1.0);
  scope.update(tap);
  scope.recent(64, d, a);
  EXPECT_EQ(a, more);
}

TEST(PredictedScope, AGuiThatFellBehindSkipsToTheSamplesStillOffered) {
  Rig rig(ResponseParams{});
  DriveTap& tap = rig.tap;
  PredictedScope& scope = rig.scope;
  const std::vector<float> drive = drive_signal(DriveTap::kRingSize * 2);
  for (std::size_t b = 0; b * 64 < drive.size(); ++b) {
    tap.write(std::span<const float>(drive).subspan(b * 64, 64), static_cast<double>(b * 64) / kRate);
  }
  scope.update(tap);
  EXPECT_EQ(scope.modelled(), DriveTap::kRingSize / 2);
  EXPECT_EQ(scope.skipped(), drive.size() - DriveTap::kRingSize / 2);
  std::vector<float> d, a;
  scope.recent(100, d, a);
  EXPECT_EQ(d, std::vector<float>(drive.end() - 100, drive.end()));
}

}  // namespace
}  // namespace vimg::editor
