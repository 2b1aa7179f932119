#pragma once
// A DriveSink in front of the output that runs every sample through the actuator chain
// (primitives/actuator/actuator_chain.hpp): the equalizer (`--equalize`) and/or the modelled
// acceleration (`vimg render --signal acceleration`). The one place the chain meets a drive
// stream: `vimg render` puts it before its file, `vimg-player --equalize` before its output, so the
// player drives the actuator as the render's WAV would. The chain keeps its state from block to
// block and starts at rest on open().
//
// Threads: construction and open() on the control thread, before the stream starts (open() designs
// the chain at the stream's rate and sizes the block buffer for the largest block the real-time
// renderer writes: the output's minimum block or 1/50 s); write() on the render thread: no
// allocation, no lock, no throw (a block longer than the buffer is equalized piece by piece); close()
// and the accessors on the control thread.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "player/drive_sink.hpp"
#include "primitives/actuator/actuator_chain.hpp"

namespace vimg {

class ActuatorSink final : public DriveSink {
 public:
  ActuatorSink(DriveSink& output, const ResponseParams& params, OutputSignal signal, bool equalize)
      : output_(output), params_(params), signal_(signal), equalize_(equalize) {}

  void open(double sample_rate_hz) override;
  void write(std::span<const float> drive, double block_start_time_s) override;
  void close() override { output_.close(); }
  bool paces_stream() const override { return output_.paces_stream(); }
  std::size_t min_block_samples() const override { return output_.min_block_samples(); }
  double output_latency_s() const override { return output_.output_latency_s(); }

  // False when the chain is the identity (e.g. equalizing an ideal, voice-coil or ERM actuator, or
  // the drive of any): the drive passes unchanged.
  bool changes_drive() const { return chain_ && !chain_->is_identity(); }
  // Samples of this stream the equalizer clamped to the drive limit (since open()).
  std::uint64_t clamped_samples() const { return chain_ ? chain_->clamped_samples() : 0; }

 private:
  DriveSink& output_;
  ResponseParams params_;
  OutputSignal signal_;
  bool equalize_;
  std::optional<ActuatorChain> chain_;
  std::vector<float> buffer_;
  double sample_rate_hz_ = 0.0;
};

}  // namespace vimg
