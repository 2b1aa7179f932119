#include "apps/vimg-player/study_text.hpp"

#include <cmath>
#include <cstdio>

#include "apps/vimg-player/status_overlay.hpp"

namespace vimg::player_app {

namespace {
constexpr int kBodyPoints = 20;
constexpr int kTitlePoints = 34;
}  // namespace

StudyText::StudyText() {
  if (TTF_Init() != 0) {
    std::fprintf(stderr, "vimg-player: the study's screens have no text: cannot start SDL_ttf: %s\n", TTF_GetError());
    return;
  }
  started_ = true;
  body_ = TTF_OpenFont(kOverlayFontPath, kBodyPoints);
  title_ = TTF_OpenFont(kOverlayFontPath, kTitlePoints);
  if (body_ == nullptr || title_ == nullptr) {
    std::fprintf(stderr,
                 "vimg-player: the study's screens have no text: cannot open the font %s (%s); install the Debian "
                 "package fonts-dejavu-core\n",
                 kOverlayFontPath, TTF_GetError());
  }
}

StudyText::~StudyText() {
  if (body_ != nullptr) TTF_CloseFont(body_);
  if (title_ != nullptr) TTF_CloseFont(title_);
  if (started_) TTF_Quit();
}

int StudyText::line_height(TextSize size) const {
  TTF_Font* f = font(size);
  return f != nullptr ? TTF_FontLineSkip(f) : (size == TextSize::title ? 40 : 24);
}

void StudyText::draw(SDL_Renderer* renderer, const std::string& text, double x, double y, TextSize size,
                     TextAlign align, SDL_Color colour) const {
  TTF_Font* f = font(size);
  if (f == nullptr || text.empty()) return;
  SDL_Surface* surface = TTF_RenderUTF8_Blended(f, text.c_str(), colour);
  if (surface == nullptr) return;
  SDL_Texture* texture = SDL_CreateTextureFromSurface(renderer, surface);
  if (texture != nullptr) {
    double left = x;
    if (align == TextAlign::centre) left = x - surface->w / 2.0;
    if (align == TextAlign::right) left = x - surface->w;
    const SDL_Rect where{static_cast<int>(std::lround(left)), static_cast<int>(std::lround(y)), surface->w, surface->h};
    SDL_RenderCopy(renderer, texture, nullptr, &where);
    SDL_DestroyTexture(texture);
  }
  SDL_FreeSurface(surface);
}

void StudyText::draw_centred(SDL_Renderer* renderer, const std::string& text, double x, double centre_y,
                             TextSize size, TextAlign align, SDL_Color colour) const {
  draw(renderer, text, x, centre_y - line_height(size) / 2.0, size, align, colour);
}

}  // namespace vimg::player_app
