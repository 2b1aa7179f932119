#include "editor/core/drive_tap.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "player/drive_sinks.hpp"
#include "player/touch_event.hpp"

namespace vimg::editor {
namespace {

constexpr double kRate = 8000.0;

TEST(DriveTap, ForwardsEveryBlockUnchanged) {
  MemorySink memory;
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> a(64, 0.25f), b(64, -0.5f);
  tap.write(a, 10.0);
  tap.write(b, 10.008);
  tap.close();
  ASSERT_EQ(memory.samples().size(), 128u);
  EXPECT_FLOAT_EQ(memory.samples()[0], 0.25f);
  EXPECT_FLOAT_EQ(memory.samples()[127], -0.5f);
  EXPECT_TRUE(memory.closed());
  std::vector<float> recent;
  tap.copy_recent(recent, 100);
  ASSERT_EQ(recent.size(), 100u);
  EXPECT_FLOAT_EQ(recent.front(), 0.25f);
  EXPECT_FLOAT_EQ(recent.back(), -0.5f);
}

TEST(DriveTap, MapsRendererTimeToOutputTimeAcrossSkippedBlocks) {
  MemorySink memory;
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> block(64, 0.0f);  // 8 ms
  tap.write(block, 10.000);
  tap.write(block, 10.008);
  tap.write(block, 10.040);  // the renderer fell behind and skipped 24 ms
  EXPECT_NEAR(tap.first_block_time_s(), 10.0, 1e-12);
  EXPECT_NEAR(tap.output_time_s(10.004), 0.004, 1e-9);
  EXPECT_NEAR(tap.output_time_s(10.012), 0.012, 1e-9);
  EXPECT_NEAR(tap.output_time_s(10.030), 0.016, 1e-9) << "inside the gap: its end";
  EXPECT_NEAR(tap.output_time_s(10.041), 0.017, 1e-9);
}

TEST(DriveTap, RecordsOneLatencyPerDriveOnset) {
  MemorySink memory;
  DriveTap tap(memory);
  tap.open(kRate);
  const std::vector<float> silent(64, 0.0f), driven(64, 0.3f);
  tap.note_event(monotonic_s());
  tap.write(silent, 0.0);
  tap.write(driven, 0.008);
  tap.write(driven, 0.016);
  tap.write(silent, 0.024);
  tap.write(driven, 0.032);
  const std::vector<double> latencies = tap.latencies_s();
  ASSERT_EQ(latencies.size(), 2u);
  for (double l : latencies) EXPECT_GE(l, 0.0);
}

}  // namespace
}  // namespace vimg::editor
