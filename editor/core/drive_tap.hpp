#pragma once
// A DriveSink in front of the chosen output: it forwards every block unchanged and keeps what the
// editor shows about it (the oscilloscope's recent samples, the time base of the output, and the
// time from an input event to the first drive it caused). It is transparent to the renderer: it
// says the output paces the stream when the output does, and asks for the output's minimum block.
// Threads: open(), close() and the accessors on the control/GUI thread; write() on the render
// thread, lock-free, never allocating; note_event() on the input thread.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "player/drive_sink.hpp"

namespace vimg::editor {

class DriveTap final : public DriveSink {
 public:
  explicit DriveTap(DriveSink& output) : output_(output) {}

  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override { output_.close(); }
  bool paces_stream() const override { return output_.paces_stream(); }
  std::size_t min_block_samples() const override { return output_.min_block_samples(); }
  double output_latency_s() const override { return output_.output_latency_s(); }

  double sample_rate_hz() const { return sample_rate_hz_.load(std::memory_order_acquire); }
  // The renderer-clock time of the first sample written (NaN before the first block).
  double first_block_time_s() const { return first_block_time_s_.load(std::memory_order_acquire); }

  // The most recent samples, oldest first (GUI thread).
  void copy_recent(std::vector<float>& out, std::size_t count) const;
  // How many samples were written since open() (GUI thread).
  std::uint64_t written() const { return written_.load(std::memory_order_acquire); }
  // The samples written from sample `first` on, oldest first, into `out` (replacing it), and the
  // index of the sample after the last one copied (the next call's `first`). Samples older than
  // kRingSize / 2 are no longer offered (the render thread may be overwriting them): then `out`
  // starts later than `first`, and `skipped` (if given) says how many were left out. GUI thread;
  // PredictedScope follows the drive with it.
  std::uint64_t copy_since(std::uint64_t first, std::vector<float>& out, std::uint64_t* skipped = nullptr) const;

  // Called by the input thread when it pushes an event (monotonic seconds).
  void note_event(double event_time_s) { last_event_time_s_.store(event_time_s, std::memory_order_release); }
  // Latencies from the last input event to the write() of a block that starts drive after
  // silence, in seconds; at most kMaxLatencies are kept.
  std::vector<double> latencies_s() const;

  // Maps a time on the renderer's clock (the block times; RealtimeRenderer::renderer_time_s()
  // puts an event time on it) to seconds into the output (0 = the first sample). A renderer paced
  // by deadlines skips blocks when it falls far behind, so the two differ by the skipped time;
  // with an output that paces the stream the block times follow the samples exactly. Exact for
  // the samples written so far; times inside a skipped gap map to its end.
  double output_time_s(double renderer_time_s) const;

  static constexpr std::size_t kRingSize = 8192;
  static constexpr std::size_t kMaxSegments = 4096;
  static constexpr std::size_t kMaxLatencies = 1024;

 private:
  DriveSink& output_;
  std::atomic<double> sample_rate_hz_{0.0};
  std::atomic<double> first_block_time_s_;
  std::array<std::atomic<float>, kRingSize> ring_{};
  std::atomic<std::uint64_t> written_{0};
  std::atomic<double> last_event_time_s_{0.0};
  bool was_silent_ = true;  // render thread only
  std::array<std::atomic<double>, kMaxLatencies> latencies_{};
  // Runs of contiguous blocks: where each starts on the renderer clock and in samples.
  std::array<std::atomic<double>, kMaxSegments> segment_time_s_{};
  std::array<std::atomic<std::uint64_t>, kMaxSegments> segment_sample_{};
  std::atomic<std::size_t> segment_count_{0};
  double next_block_time_s_ = 0.0;  // render thread only
  std::uint64_t samples_total_ = 0;  // render thread only
  std::atomic<std::size_t> latency_count_{0};
};

}  // namespace vimg::editor
