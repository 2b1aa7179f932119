#include "apps/vimg-player/status_text.hpp"

#include <cstdio>
#include <utility>

#include "realtime/realtime_priority.hpp"

namespace vimg::player_app {

StatusText::StatusText(std::string output, std::string scale_source, double px_per_mm)
    : output_(std::move(output)), scale_source_(std::move(scale_source)), px_per_mm_(px_per_mm) {}

void StatusText::note(std::string message) {
  messages_.push_back(std::move(message));
  while (messages_.size() > kMessages) messages_.pop_front();
}

std::vector<std::string> StatusText::lines(const LoopStats& stats, std::uint64_t underruns, bool device_gone) const {
  char line[160];
  std::vector<std::string> lines;
  lines.push_back("Output " + output_);
  std::snprintf(line, sizeof line, "Loop %.0f Hz  jitter p50 %.2f ms  p99 %.2f ms  max %.2f ms", stats.measured_rate_hz,
                stats.jitter_p50_s * 1e3, stats.jitter_p99_s * 1e3, stats.jitter_max_s * 1e3);
  lines.emplace_back(line);
  lines.push_back("Render thread " + describe(stats.priority));
  std::snprintf(line, sizeof line, "Underruns %llu  overruns %llu  dropped %llu  contacts %llu",
                static_cast<unsigned long long>(underruns), static_cast<unsigned long long>(stats.overruns),
                static_cast<unsigned long long>(stats.dropped_events),
                static_cast<unsigned long long>(stats.active_contacts));
  lines.emplace_back(line);
  std::snprintf(line, sizeof line, "Scale %.2f px/mm (%s)", px_per_mm_, scale_source_.c_str());
  lines.emplace_back(line);
  if (device_gone) lines.emplace_back("Device gone: output paused, reconnecting");
  lines.insert(lines.end(), messages_.begin(), messages_.end());
  return lines;
}

}  // namespace vimg::player_app
