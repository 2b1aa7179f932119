#pragma once
// The output playing mode drives: a DriveSink, and what its device says while it plays. A hal
// output (hal/output_spec.hpp: audio, WAV, DRV2605L, BOS1901, HID) says what its device service
// formats: faults (a DRV2605L over-current, an I2C transfer that failed), a device gone and
// reconnected, a WAV file that could not be written; a CSV file or no output says nothing.
// Threads: the sink as any DriveSink; take_messages() on the GUI thread.
#include <memory>
#include <string>
#include <vector>

#include "hal/output_spec.hpp"
#include "player/drive_sink.hpp"

namespace vimg::editor {

class PlayOutput : public DriveSink {
 public:
  // The messages since the last call, oldest first (hal Output::take_messages()).
  virtual std::vector<std::string> take_messages() { return {}; }
};

// A hal output (its devices, its sink and its device service) as one PlayOutput.
std::unique_ptr<PlayOutput> play_output(std::unique_ptr<Output> output);
// Any other sink, which has nothing to say.
std::unique_ptr<PlayOutput> play_output(std::unique_ptr<DriveSink> sink);

}  // namespace vimg::editor
