// The actuator chain on a drive stream (vimg-player --equalize, vimg render --signal/--equalize):
// the output receives the chain applied to the rendered drive, sample for sample, whatever the
// blocks; without an equalizing actuator the drive passes unchanged.
#include "player/actuator_sink.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../actuator/model_params.hpp"
#include "../actuator/test_drive.hpp"
#include "player/drive_sinks.hpp"

namespace vimg {
namespace {

constexpr double kRate = 8000.0;

using test::lra;

std::vector<float> drive_signal(std::size_t n) { return test::two_tone_drive(n, kRate); }

// Writes `drive` in blocks of the given sizes (cycled), as the renderer does.
void write_blocks(DriveSink& sink, const std::vector<float>& drive, const std::vector<std::size_t>& sizes) {
  std::size_t done = 0, k = 0;
  while (done < drive.size()) {
    const std::size_t n = std::min(sizes[k++ % sizes.size()], drive.size() - done);
    sink.write(std::span<const float>(drive).subspan(done, n), static_cast<double>(done) / kRate);
    done += n;
  }
}

TEST(ActuatorSink, TheOutputGetsTheEqualizerOfTheDriveAsAnOfflineRenderDoes) {
  const std::vector<float> drive = drive_signal(4000);
  ActuatorChain offline(lra(), kRate, OutputSignal::drive, true);
  std::vector<float> expected(drive.size());
  for (std::size_t i = 0; i < drive.size(); ++i) expected[i] = offline.process(drive[i]);

  // Blocks of 1 ms, of 1/50 s, and longer than the sink's buffer (split inside).
  for (const std::vector<std::size_t>& sizes : {std::vector<std::size_t>{8}, {160, 7, 33}, {1000}}) {
    MemorySink memory;
    ActuatorSink sink(memory, lra(), OutputSignal::drive, true);
    sink.open(kRate);
    EXPECT_TRUE(sink.changes_drive());
    write_blocks(sink, drive, sizes);
    sink.close();
    ASSERT_EQ(memory.samples().size(), drive.size());
    for (std::size_t i = 0; i < drive.size(); ++i) ASSERT_EQ(memory.samples()[i], expected[i]) << i;
    EXPECT_TRUE(memory.closed());
    EXPECT_EQ(sink.clamped_samples(), 0u);
  }
  // It does change the drive (the resonance is attenuated), and stays far inside the drive limit
  // without the clamp: the equalizer's filter alone peaks at 0.51.
  Equalizer filter(lra(), kRate);
  double diff = 0.0;
  double peak = 0.0;
  for (std::size_t i = 0; i < drive.size(); ++i) {
    diff += std::abs(expected[i] - drive[i]);
    peak = std::max(peak, std::fabs(filter.filter(drive[i])));
  }
  EXPECT_GT(diff, 100.0);
  EXPECT_LE(peak, 0.51);
}

TEST(ActuatorSink, CountsTheSamplesTheEqualizerClamped) {
  // Full-scale square waves at the resonance overshoot beyond the drive limit before the clamp.
  std::vector<float> drive(8000);
  for (std::size_t i = 0; i < drive.size(); ++i) drive[i] = (i / 23) % 2 == 0 ? 1.0f : -1.0f;
  Equalizer filter(lra(), kRate);
  std::uint64_t beyond = 0;
  for (const float d : drive) beyond += std::fabs(filter.filter(d)) > 1.0 ? 1u : 0u;
  ASSERT_GT(beyond, 0u);
  MemorySink memory;
  ActuatorSink sink(memory, lra(), OutputSignal::drive, true);
  sink.open(kRate);
  write_blocks(sink, drive, {160});
  EXPECT_EQ(sink.clamped_samples(), beyond);
  for (const float v : memory.samples()) ASSERT_LE(std::fabs(v), 1.0f);
  sink.open(kRate);  // a new stream starts counting again
  EXPECT_EQ(sink.clamped_samples(), 0u);
}

TEST(ActuatorSink, ABlockLongerThanTheBufferKeepsItsTimes) {
  struct Times final : DriveSink {
    std::vector<std::pair<double, std::size_t>> blocks;
    void open(double) override {}
    void write(std::span<const float> d, double t) override { blocks.emplace_back(t, d.size()); }
    void close() override {}
  } times;
  ActuatorSink sink(times, lra(), OutputSignal::drive, true);
  sink.open(kRate);
  const std::vector<float> drive = drive_signal(400);  // the buffer holds 1/50 s = 160 samples
  sink.write(drive, 2.0);
  ASSERT_EQ(times.blocks.size(), 3u);
  EXPECT_DOUBLE_EQ(times.blocks[1].first, 2.0 + 160 / kRate);
  EXPECT_EQ(times.blocks[2].second, 80u);
}

TEST(ActuatorSink, ActuatorsWithAFlatBandPassTheDriveUnchanged) {
  for (const ResponseModel model : {ResponseModel::ideal, ResponseModel::voice_coil, ResponseModel::erm}) {
    ResponseParams p;
    p.model = model;
    MemorySink memory;
    ActuatorSink sink(memory, p, OutputSignal::drive, true);
    sink.open(kRate);
    EXPECT_FALSE(sink.changes_drive());
    const std::vector<float> drive = drive_signal(1000);
    write_blocks(sink, drive, {64});
    EXPECT_EQ(memory.samples(), drive);
  }
}

}  // namespace
}  // namespace vimg
