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
  lines.push_back("OUTPUT " + output_);
  std::snprintf(line, sizeof line, "LOOP %.0f HZ  JITTER P50 %.2f MS  P99 %.2f MS  MAX %.2f MS", stats.measured_rate_hz,
                stats.jitter_p50_s * 1e3, stats.jitter_p99_s * 1e3, stats.jitter_max_s * 1e3);
  lines.emplace_back(line);
  lines.push_back("RENDER THREAD " + describe(stats.priority));
  std::snprintf(line, sizeof line, "UNDERRUNS %llu  OVERRUNS %llu  DROPPED %llu  CONTACTS %llu",
                static_cast<unsigned long long>(underruns), static_cast<unsigned long long>(stats.overruns),
                static_cast<unsigned long long>(stats.dropped_events),
                static_cast<unsigned long long>(stats.active_contacts));
  lines.emplace_back(line);
  std::snprintf(line, sizeof line, "SCALE %.2f PX/MM (%s)", px_per_mm_, scale_source_.c_str());
  lines.emplace_back(line);
  if (device_gone) lines.emplace_back("DEVICE GONE: OUTPUT PAUSED, RECONNECTING");
  lines.insert(lines.end(), messages_.begin(), messages_.end());
  return lines;
}

}  // namespace vimg::player_app
