#pragma once
// One run of the haptic loop, watched from the control thread. vimg-force's scene session runs one;
// the location study runs one per phase (waiting for the participant, then each trial), so that every
// force either sends has gone through the same loop and the whole safety stack, and ends the same way:
//
//   the caller has started the loop; every 10 ms this thread checks, in order, for a signal (SIGINT,
//   SIGTERM), a fault of the loop (a device error, stale input, overruns) and the caller's own end
//   (`finished`), then calls `tick` (status line, keys); at the end it stops the loop, which sends
//   zero force before stop() returns. Nothing else happens before the device is at rest.
#include <atomic>
#include <functional>
#include <string>

#include "player/haptic/haptic_loop.hpp"

namespace vimg::force_app {

struct LoopWatch {
  std::function<bool()> finished;             // the run has done its job (may be empty: never)
  std::function<void(double elapsed_s)> tick;  // after each check, with the wall time since the start
};

struct LoopRunEnd {
  enum class Why { finished, signal, fault };
  Why why = Why::finished;
  int signal_number = 0;  // SIGINT or SIGTERM when why == signal
  std::string fault;      // the loop's fault text when why == fault
  // "SIGINT", "SIGTERM", "device fault: ..." or `finished_reason`.
  std::string reason(const std::string& finished_reason) const;
  // 0, 130 (SIGINT), 143 (SIGTERM) or 1 (fault).
  int exit_code() const;
};

// Runs until the end (see above); the loop is stopped, the device sent zero force, when it returns.
LoopRunEnd watch_loop(HapticLoop& loop, const std::atomic<int>& signal_received, const LoopWatch& watch);

// The exit status for a signal caught before anything moved: 130 or 143.
int exit_code_for_signal(int signal_number);

// The line vimg-force prints once the loop runs: "vimg-force: DEVICE at 1000 Hz, clamp 3.3 N, slew 1
// N/ms, SCHEDULING".
std::string loop_announcement(const HapticLoop& loop, const std::string& device_description);

}  // namespace vimg::force_app
