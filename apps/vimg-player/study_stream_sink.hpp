#pragma once
// The scripted matching test's one output stream. Each trial's rubbing is rendered with the offline
// renderer (player/offline_render.hpp: the same engine as the real-time thread, the same samples on
// any machine), one trial after another, into this sink, which keeps the output open from the first
// trial to the last (finish()), numbers the blocks on one time line and plays them at the gesture's
// own pace: a sink that paces the stream (a sound card) does it itself; any other (a file, an I2C
// driver) is held to absolute deadlines on CLOCK_MONOTONIC (realtime/clock.hpp). So a scripted
// trial lasts as long as its gesture and its ring-down, whatever the machine's speed, and so does
// what the output receives.
// Threads: one (the scripted run's).
#include <cstddef>
#include <cstdint>
#include <span>

#include "player/drive_sink.hpp"

namespace vimg::player_app {

class StudyStreamSink final : public DriveSink {
 public:
  explicit StudyStreamSink(DriveSink& output) : output_(output) {}

  // The first call opens the output; later ones (each trial's render) change nothing.
  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  // The end of one trial's render: the output stays open.
  void close() override {}
  bool paces_stream() const override { return output_.paces_stream(); }
  std::size_t min_block_samples() const override { return output_.min_block_samples(); }
  double output_latency_s() const override { return output_.output_latency_s(); }

  // Closes the output (zero drive, the file completed). Once.
  void finish();
  std::uint64_t samples() const { return samples_; }

 private:
  DriveSink& output_;
  bool open_ = false;
  bool finished_ = false;
  double sample_rate_hz_ = 0.0;
  std::int64_t start_ns_ = 0;
  std::uint64_t samples_ = 0;
};

}  // namespace vimg::player_app
