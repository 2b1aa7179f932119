#pragma once
// Where rendered drive goes: a file, memory, an audio device or an actuator driver.
// The renderer calls these from its own thread; write() may block only on the device itself.
//
// One clock per stream: a sink whose device plays at its own clock (a sound card) says so with
// paces_stream(). Its write() blocks until the device has room, and the renderer then renders
// block after block without sleeping on CLOCK_MONOTONIC and without ever skipping. A sink without
// a clock (a file, memory, an I2C driver with no FIFO) is paced by the renderer's deadlines.
#include <cstddef>
#include <span>

namespace vimg {

class DriveSink {
 public:
  virtual ~DriveSink() = default;

  // Called once before the first block.
  virtual void open(double sample_rate_hz) = 0;

  // One block of normalized drive in [-1, 1], the first sample at block_start_time_s.
  virtual void write(std::span<const float> drive, double block_start_time_s) = 0;

  // Puts the output to rest (zero drive, actuator standby) and completes any file. Called on
  // normal stop and on error; must be safe to call more than once.
  virtual void close() = 0;

  // True when write() blocks on a device that consumes samples at its own clock (see above).
  virtual bool paces_stream() const { return false; }

  // The smallest block the sink works with (e.g. a device that wants whole FIFO loads); the
  // real-time renderer never writes smaller blocks. Valid after open(). Files and memory take
  // anything.
  virtual std::size_t min_block_samples() const { return 1; }

  // The output path's own latency: from a sample's block time to the actuator receiving it (a
  // sound card's buffers, a driver's FIFO). Valid after open(). The live tracker predicts each
  // finger this much further ahead, on top of the touch panel's latency (docs/latency.md). Files,
  // memory and drivers that apply a sample when written: 0.
  virtual double output_latency_s() const { return 0.0; }
};

}  // namespace vimg
