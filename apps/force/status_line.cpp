#include "apps/force/status_line.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace vimg::force_app {

std::string format_status_line(const HapticLoopStatus& s) {
  char text[160];
  std::snprintf(text, sizeof text, "%.1f Hz  jitter p99 %.0f us  %llu overruns  max |F| %.2f N  %s", s.timing.rate_hz,
                s.timing.jitter_p99_us, static_cast<unsigned long long>(s.timing.overruns), s.max_force_N, describe(s.state));
  return text;
}

std::string format_trial_status(std::size_t trial, std::size_t total, LocationMetaphor metaphor, double elapsed_s) {
  const double seconds = std::isfinite(elapsed_s) && elapsed_s > 0.0 ? std::floor(elapsed_s) : 0.0;
  char text[120];
  std::snprintf(text, sizeof text, "trial %zu of %zu  %s  elapsed %.0f s", trial, total,
                metaphor == LocationMetaphor::roughness ? "roughness" : "transition cue", seconds);
  return text;
}

TerminalStatusLine::TerminalStatusLine() : terminal_(::isatty(STDERR_FILENO) == 1) {}

void TerminalStatusLine::show(const std::string& text) {
  if (!terminal_) return;
  std::fprintf(stderr, "\r%s\x1b[K", text.c_str());
  shown_ = true;
}

void TerminalStatusLine::finish() {
  if (shown_) std::fputc('\n', stderr);
  shown_ = false;
}

void TerminalStatusLine::settle(const std::string& text) {
  if (terminal_) {
    std::fprintf(stderr, "\r%s\x1b[K\n", text.c_str());
  } else {
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  shown_ = false;
}

}  // namespace vimg::force_app
