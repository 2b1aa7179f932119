#include "apps/vimg-player/status_overlay.hpp"

#include <algorithm>

#include "apps/vimg-player/tiny_font.hpp"

namespace vimg::player_app {

void draw_status_panel(SDL_Renderer* renderer, const std::vector<std::string>& lines) {
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
