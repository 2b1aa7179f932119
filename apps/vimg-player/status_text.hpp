#pragma once
// The text of the status overlay, apart from drawing it: the output, the loop's rate and jitter,
// the render thread's scheduling outcome (describe() of LoopStats::priority, with the reason when
// SCHED_FIFO was refused), counters, the scale, whether the device is gone, and the newest fault
// messages from the device service.
// Threads: the UI thread (it allocates).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "player/realtime_renderer.hpp"

namespace vimg::player_app {

class StatusText {
 public:
  static constexpr std::size_t kMessages = 3;  // the newest ones shown

  StatusText(std::string output, std::string scale_source, double px_per_mm);
  void note(std::string message);
  std::vector<std::string> lines(const LoopStats& stats, std::uint64_t underruns, bool device_gone) const;

 private:
  std::string output_;
  std::string scale_source_;
  double px_per_mm_;
  std::deque<std::string> messages_;
};

}  // namespace vimg::player_app
