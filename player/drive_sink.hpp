#pragma once
// Where rendered drive goes: a file, memory, an audio device or an actuator driver.
// The renderer calls these from its own thread; write() may block only on the device itself.
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
};

}  // namespace vimg
