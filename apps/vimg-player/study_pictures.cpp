#include "apps/vimg-player/study_pictures.hpp"

#include <cstdio>

#include "storage/palette.hpp"
#include "storage/picture.hpp"

namespace vimg::player_app {

StudyPictures::~StudyPictures() {
  for (auto& e : entries_) {
    if (e.texture != nullptr) SDL_DestroyTexture(e.texture);
  }
}

const StudyPictures::Entry& StudyPictures::entry(const Image& image, double px_per_mm) {
  for (const auto& e : entries_) {
    if (e.image == &image && e.px_per_mm == px_per_mm) return e;
  }
  Entry e{&image, px_per_mm};
  RgbRaster raster;
  if (const auto error = draw_picture(image, px_per_mm, raster)) {
    std::fprintf(stderr, "vimg-player: a picture is shown without its primitives: %s\n", error->c_str());
  } else {
    e.texture = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STATIC, raster.width, raster.height);
    if (e.texture == nullptr || SDL_UpdateTexture(e.texture, nullptr, raster.rgb.data(), raster.width * 3) != 0) {
      std::fprintf(stderr, "vimg-player: cannot show a picture: %s\n", SDL_GetError());
    } else {
      e.width_px = raster.width;
      e.height_px = raster.height;
    }
  }
  entries_.push_back(e);
  return entries_.back();
}

void StudyPictures::draw(const Image& image, double px_per_mm, double x, double y) {
  const Entry& e = entry(image, px_per_mm);
  const SDL_FRect canvas{static_cast<float>(x), static_cast<float>(y), static_cast<float>(image.width_mm * px_per_mm),
                         static_cast<float>(image.height_mm * px_per_mm)};
  if (e.texture != nullptr) {
    const SDL_FRect where{canvas.x, canvas.y, static_cast<float>(e.width_px), static_cast<float>(e.height_px)};
    SDL_RenderCopyF(renderer_, e.texture, nullptr, &where);
  } else {
    SDL_SetRenderDrawColor(renderer_, palette::kBackground.r, palette::kBackground.g, palette::kBackground.b, 255);
    SDL_RenderFillRectF(renderer_, &canvas);
  }
  SDL_SetRenderDrawColor(renderer_, palette::kCanvasBorder.r, palette::kCanvasBorder.g, palette::kCanvasBorder.b, 255);
  SDL_RenderDrawRectF(renderer_, &canvas);
}

}  // namespace vimg::player_app
