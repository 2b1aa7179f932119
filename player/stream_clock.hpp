#pragma once
// The renderer clock of a stream that its sink paces (DriveSink::paces_stream(): a sound card
// plays at its own crystal, not at CLOCK_MONOTONIC).
//
// Stream time. Sample n is at start_s + n / rate: exactly the samples written, uniform, never
// skipped, whatever the device clock does. Block times passed to the sink are stream times.
//
// Events. Touch events are stamped with monotonic_s(). They are mapped onto the stream by adding
// an offset that follows, slowly, how far the stream time of the block being rendered is ahead of
// CLOCK_MONOTONIC at that moment. Each block observes raw_k = T_k - now_k and
//     offset_k = offset_{k-1} + a_k * (raw_k - offset_{k-1}),   a_k = max(1 / (k + 1), block_s / tau)
// (a running mean while fewer than tau of blocks have been seen, then a first-order low-pass
// with time constant tau). So an event stamped now maps to about the time of the block rendered
// now, as it does when deadlines pace the loop, and:
//   - the device queue filling at the start (raw jumps by the queue length) and the device
//     taking whole buffers at a time (raw wobbles by a buffer) move the mapping by their mean
//     only, not sample by sample;
//   - a device clock off by a fraction d makes raw a ramp of slope d; the mapping follows it with
//     a lag of d * tau (1 % at tau = 0.25 s: 2.5 ms), bounded however long the stream plays. Without
//     the offset the error would grow by d per second (36 s an hour) and events would soon look
//     stale (dropped) or far in the future.
// Renderer-clock times given to other parts (the drive tap, recorded gestures) are stream times;
// to_stream_s() converts an event time with the current offset.
//
// Threads: one thread at a time (the render thread); plain arithmetic, never allocates or blocks.
#include <cstdint>

namespace vimg {

class StreamClock {
 public:
  static constexpr double kDefaultTimeConstant_s = 0.25;

  explicit StreamClock(double sample_rate_hz, double time_constant_s = kDefaultTimeConstant_s);

  // Sample 0 is at start_s (CLOCK_MONOTONIC when the stream starts); the offset starts at 0.
  void start(double start_s);

  double sample_time_s(std::uint64_t sample) const {
    return start_s_ + static_cast<double>(sample) / sample_rate_hz_;
  }

  // The block that starts at `sample` is being rendered at CLOCK_MONOTONIC now_s.
  void observe(std::uint64_t sample, double now_s);

  // Stream time minus CLOCK_MONOTONIC time, as followed so far.
  double offset_s() const { return offset_s_; }
  double to_stream_s(double monotonic_time_s) const { return monotonic_time_s + offset_s_; }
  double to_monotonic_s(double stream_time_s) const { return stream_time_s - offset_s_; }

 private:
  double sample_rate_hz_;
  double time_constant_s_;
  double start_s_ = 0.0;
  double offset_s_ = 0.0;
  std::uint64_t last_sample_ = 0;
  std::uint64_t observations_ = 0;
};

}  // namespace vimg
