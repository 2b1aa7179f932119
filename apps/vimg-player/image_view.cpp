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
  PictureTexture picture;

  bool matches(SDL_Renderer* r, const Image& i, double scale) const {
    return r == renderer && &i == image && i.children.size() == primitives && scale == px_per_mm;
  }
};

PictureCache& cache() {
  static PictureCache value;
  return value;
}

void rebuild(PictureCache& c, SDL_Renderer* renderer, const Image& image, double px_per_mm) {
  if (c.picture.texture != nullptr && c.renderer == renderer) SDL_DestroyTexture(c.picture.texture);
  c = PictureCache{renderer, &image, image.children.size(), px_per_mm,
                   make_picture_texture(renderer, image, px_per_mm,
                                        {"the image is shown without its primitives", "cannot show the picture"})};
}

}  // namespace

PictureTexture make_picture_texture(SDL_Renderer* renderer, const Image& image, double px_per_mm,
                                    const PictureMessages& messages) {
  PictureTexture picture;
  RgbRaster raster;
  if (const auto error = draw_picture(image, px_per_mm, raster)) {
    std::fprintf(stderr, "vimg-player: %s: %s\n", messages.not_drawn, error->c_str());
    return picture;
  }
  picture.texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STATIC, raster.width, raster.height);
  if (picture.texture == nullptr || SDL_UpdateTexture(picture.texture, nullptr, raster.rgb.data(), raster.width * 3) != 0) {
    std::fprintf(stderr, "vimg-player: %s: %s\n", messages.not_shown, SDL_GetError());
    return picture;
  }
  picture.width_px = raster.width;
  picture.height_px = raster.height;
  return picture;
}

void draw_picture_canvas(SDL_Renderer* renderer, const PictureTexture& picture, const SDL_FRect& canvas) {
  if (picture.texture != nullptr) {
    const SDL_FRect where{canvas.x, canvas.y, static_cast<float>(picture.width_px), static_cast<float>(picture.height_px)};
    SDL_RenderCopyF(renderer, picture.texture, nullptr, &where);
  } else {
    SDL_SetRenderDrawColor(renderer, palette::kBackground.r, palette::kBackground.g, palette::kBackground.b, 255);
    SDL_RenderFillRectF(renderer, &canvas);
  }
  SDL_SetRenderDrawColor(renderer, palette::kCanvasBorder.r, palette::kCanvasBorder.g, palette::kCanvasBorder.b, 255);
  SDL_RenderDrawRectF(renderer, &canvas);
}

void draw_image(SDL_Renderer* renderer, const Image& image, const ViewTransform& view) {
  PictureCache& c = cache();
  if (!c.matches(renderer, image, view.px_per_mm)) rebuild(c, renderer, image, view.px_per_mm);
  const SDL_FRect canvas{static_cast<float>(std::round(view.to_x_px(0.0))), static_cast<float>(std::round(view.to_y_px(0.0))),
                         static_cast<float>(image.width_mm * view.px_per_mm),
                         static_cast<float>(image.height_mm * view.px_per_mm)};
  draw_picture_canvas(renderer, c.picture, canvas);
}

}  // namespace vimg::player_app
