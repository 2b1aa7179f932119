#pragma once
// The one-line status vimg-force rewrites in place on a terminal:
//   a scene, each second:   "1000.0 Hz  jitter p99 45 us  0 overruns  max |F| 1.23 N  running"
//   a study trial:          "trial 3 of 14  transition cue  elapsed 12 s"
// A study's line never shows the probe's position or the target: that would give the answer away.
#include <cstddef>
#include <string>

#include "player/haptic/haptic_loop.hpp"
#include "storage/study/study_file.hpp"

namespace vimg::force_app {

std::string format_status_line(const HapticLoopStatus& status);

// "trial N of TOTAL  METAPHOR  elapsed S s" (whole seconds), the metaphor in words ("roughness",
// "transition cue").
std::string format_trial_status(std::size_t trial, std::size_t total, LocationMetaphor metaphor, double elapsed_s);

// A status line on stderr, rewritten in place ("\r...\x1b[K") when stderr is a terminal, never
// otherwise (a log file gets no carriage returns). finish() ends the line, if one was shown.
// Threads: the control thread.
class TerminalStatusLine {
 public:
  TerminalStatusLine();
  bool terminal() const { return terminal_; }
  void show(const std::string& text);
  void finish();
  // The text as a line of its own, on a terminal or not (a trial's last status stays on screen).
  void settle(const std::string& text);

 private:
  bool terminal_ = false;
  bool shown_ = false;
};

}  // namespace vimg::force_app
