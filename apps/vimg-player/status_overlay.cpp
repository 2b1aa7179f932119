#include "apps/vimg-player/status_overlay.hpp"

#include <cstdio>
#include <vector>

#include "apps/vimg-player/tiny_font.hpp"

namespace vimg::player_app {

void StatusOverlay::draw(SDL_Renderer* renderer, const LoopStats& stats, std::uint64_t underruns) const {
  char line[160];
  std::vector<std::string> lines;
  lines.push_back("OUTPUT " + output_);
  std::snprintf(line, sizeof line, "LOOP %.0f HZ %s  JITTER P50 %.2f MS  P99 %.2f MS  MAX %.2f MS",
                stats.measured_rate_hz, stats.realtime_priority ? "SCHED_FIFO" : "NORMAL PRIORITY",
                stats.jitter_p50_s * 1e3, stats.jitter_p99_s * 1e3, stats.jitter_max_s * 1e3);
  lines.emplace_back(line);
  std::snprintf(line, sizeof line, "UNDERRUNS %llu  OVERRUNS %llu  DROPPED %llu  CONTACTS %llu",
                static_cast<unsigned long long>(underruns), static_cast<unsigned long long>(stats.overruns),
                static_cast<unsigned long long>(stats.dropped_events),
                static_cast<unsigned long long>(stats.active_contacts));
  lines.emplace_back(line);
  std::snprintf(line, sizeof line, "SCALE %.2f PX/MM (%s)", px_per_mm_, scale_source_.c_str());
  lines.emplace_back(line);
  if (!last_message_.empty()) lines.push_back(last_message_);

  constexpr int kScale = 2, kLine = (kGlyphHeight + 3) * kScale, kPad = 6;
  int widest = 0;
  for (const auto& text : lines) widest = std::max(widest, text_width(text, kScale));
  SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
  SDL_SetRenderDrawColor(renderer, 0, 0, 0, 170);
  const SDL_Rect panel{0, 0, widest + 2 * kPad, static_cast<int>(lines.size()) * kLine + 2 * kPad};
  SDL_RenderFillRect(renderer, &panel);
  SDL_SetRenderDrawColor(renderer, 230, 230, 210, 255);
  int y = kPad;
  for (const auto& text : lines) {
    draw_text(renderer, kPad, y, text, kScale);
    y += kLine;
  }
}

}  // namespace vimg::player_app
