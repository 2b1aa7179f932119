#include "apps/vimg-player/status_overlay.hpp"

#include <SDL_ttf.h>

#include <algorithm>
#include <cstdio>

namespace vimg::player_app {

namespace {

// The font, opened on first use and closed at exit; `missing` once it could not be opened.
class OverlayFont {
 public:
  TTF_Font* get() {
    if (font_ == nullptr && !missing_) open();
    return font_;
  }
  ~OverlayFont() {
    if (font_ != nullptr) TTF_CloseFont(font_);
    if (started_) TTF_Quit();
  }

 private:
  void open() {
    if (TTF_Init() != 0) {
      std::fprintf(stderr, "vimg-player: no status overlay: cannot start SDL_ttf: %s\n", TTF_GetError());
      missing_ = true;
      return;
    }
    started_ = true;
    font_ = TTF_OpenFont(kOverlayFontPath, kOverlayFontPoints);
    if (font_ == nullptr) {
      std::fprintf(stderr,
                   "vimg-player: no status overlay: cannot open the font %s (%s); install the Debian package "
                   "fonts-dejavu-core\n",
                   kOverlayFontPath, TTF_GetError());
      missing_ = true;
    }
  }

  TTF_Font* font_ = nullptr;
  bool started_ = false;
  bool missing_ = false;
};

OverlayFont& overlay_font() {
  static OverlayFont font;
  return font;
}

constexpr SDL_Color kTextColour{230, 230, 210, 255};

}  // namespace

void draw_status_panel(SDL_Renderer* renderer, const std::vector<std::string>& lines) {
  TTF_Font* font = overlay_font().get();
  if (font == nullptr || lines.empty()) return;
  constexpr int kPad = 6;
  const int line_px = TTF_FontLineSkip(font);
  int widest = 0;
  for (const auto& text : lines) {
    int w = 0, h = 0;
    if (!text.empty() && TTF_SizeUTF8(font, text.c_str(), &w, &h) == 0) widest = std::max(widest, w);
  }
  SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
  SDL_SetRenderDrawColor(renderer, 0, 0, 0, 170);
  const SDL_Rect panel{0, 0, widest + 2 * kPad, static_cast<int>(lines.size()) * line_px + 2 * kPad};
  SDL_RenderFillRect(renderer, &panel);
  int y = kPad;
  for (const auto& text : lines) {
    if (!text.empty()) {
      SDL_Surface* surface = TTF_RenderUTF8_Blended(font, text.c_str(), kTextColour);
      if (surface != nullptr) {
        SDL_Texture* texture = SDL_CreateTextureFromSurface(renderer, surface);
        if (texture != nullptr) {
          const SDL_Rect where{kPad, y, surface->w, surface->h};
          SDL_RenderCopy(renderer, texture, nullptr, &where);
          SDL_DestroyTexture(texture);
        }
        SDL_FreeSurface(surface);
      }
    }
    y += line_px;
  }
}

}  // namespace vimg::player_app
