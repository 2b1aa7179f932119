#include "apps/vimg-player/image_view.hpp"

#include <cmath>
#include <cstdio>

#include "storage/palette.hpp"
#include "storage/picture.hpp"

namespace vimg::player_app {

namespace {

// The picture of the last image drawn, as a texture of the renderer that drew it.
struct PictureCache {
  SDL_Renderer* renderer = nullptr;
  const Image* image = nullptr;
  std::size_t primitives = 0;
  double px_per_mm = 0.0;
  SDL_Texture* texture = nullptr;
  int width_px = 0, height_px = 0;
  bool failed = false;

  bool matches(SDL_Renderer* r, const Image& i, double scale) const {
    return r == renderer && &i == image && i.children.size() == primitives && scale == px_per_mm;
  }
};

PictureCache& cache() {
  static PictureCache value;
  return value;
}

void rebuild(PictureCache& c, SDL_Renderer* renderer, const Image& image, double px_per_mm) {
  if (c.texture != nullptr && c.renderer == renderer) SDL_DestroyTexture(c.texture);
  c = PictureCache{renderer, &image, image.children.size(), px_per_mm};
  RgbRaster raster;
  if (const auto error = draw_picture(image, px_per_mm, raster)) {
    std::fprintf(stderr, "vimg-player: the image is shown without its primitives: %s\n", error->c_str());
    c.failed = true;
    return;
  }
  c.texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STATIC, raster.width, raster.height);
  if (c.texture == nullptr || SDL_UpdateTexture(c.texture, nullptr, raster.rgb.data(), raster.width * 3) != 0) {
    std::fprintf(stderr, "vimg-player: cannot show the picture: %s\n", SDL_GetError());
    c.failed = true;
    return;
  }
  c.width_px = raster.width;
  c.height_px = raster.height;
}

}  // namespace

void draw_image(SDL_Renderer* renderer, const Image& image, const ViewTransform& view) {
  PictureCache& c = cache();
  if (!c.matches(renderer, image, view.px_per_mm)) rebuild(c, renderer, image, view.px_per_mm);
  const SDL_FRect canvas{static_cast<float>(std::round(view.to_x_px(0.0))), static_cast<float>(std::round(view.to_y_px(0.0))),
                         static_cast<float>(image.width_mm * view.px_per_mm),
                         static_cast<float>(image.height_mm * view.px_per_mm)};
  if (c.texture != nullptr) {
    const SDL_FRect where{canvas.x, canvas.y, static_cast<float>(c.width_px), static_cast<float>(c.height_px)};
    SDL_RenderCopyF(renderer, c.texture, nullptr, &where);
  } else {
    SDL_SetRenderDrawColor(renderer, palette::kBackground.r, palette::kBackground.g, palette::kBackground.b, 255);
    SDL_RenderFillRectF(renderer, &canvas);
  }
  SDL_SetRenderDrawColor(renderer, palette::kCanvasBorder.r, palette::kCanvasBorder.g, palette::kCanvasBorder.b, 255);
  SDL_RenderDrawRectF(renderer, &canvas);
}

}  // namespace vimg::player_app
