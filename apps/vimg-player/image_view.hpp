#pragma once
// Draws a vibrotactile image at true physical size: `px_per_mm` screen pixels per millimetre,
// the canvas's top-left corner at `origin_px`. The picture is the PNG export's own
// (storage/picture.hpp, colours and stripes from storage/palette.hpp): the player, the editor and
// a converted PNG show an image the same way, surface stripes running vertically.
// Threads: the UI thread only (SDL rendering).
#include <SDL.h>

#include "primitives/image.hpp"

namespace vimg::player_app {

struct ViewTransform {
  double px_per_mm = 4.0;
  double origin_x_px = 0.0;
  double origin_y_px = 0.0;
  double to_x_px(double x_mm) const { return origin_x_px + x_mm * px_per_mm; }
  double to_y_px(double y_mm) const { return origin_y_px + y_mm * px_per_mm; }
  double to_x_mm(double x_px) const { return (x_px - origin_x_px) / px_per_mm; }
  double to_y_mm(double y_px) const { return (y_px - origin_y_px) / px_per_mm; }
};

// The picture of an image in a texture of the renderer that drew it (the owner destroys it).
struct PictureTexture {
  SDL_Texture* texture = nullptr;   // none when the picture could not be drawn
  int width_px = 0, height_px = 0;  // 0 when SDL could not take it
};

// What make_picture_texture says on stderr, after "vimg-player: ", when it cannot.
struct PictureMessages {
  const char* not_drawn;  // over the PNG pixel limit: "... is shown without its primitives", then why
  const char* not_shown;  // SDL could not make or fill the texture: "cannot show ...", then SDL's error
};

// Draws the picture of `image` at `px_per_mm` with the PNG export's painter into a new texture of
// `renderer`. A picture over the PNG pixel limit comes back without a texture; one SDL cannot take
// comes back with its size 0 (nothing is copied from it); each says so once on stderr.
PictureTexture make_picture_texture(SDL_Renderer* renderer, const Image& image, double px_per_mm,
                                    const PictureMessages& messages);

// Shows `picture` at the top-left corner of `canvas` (the bare canvas when it has no texture), and
// the canvas border.
void draw_picture_canvas(SDL_Renderer* renderer, const PictureTexture& picture, const SDL_FRect& canvas);

// Draws the image. The picture is drawn once into a texture and reused while the renderer, the
// image (its address and primitive count) and the scale stay the same; a picture over the PNG
// pixel limit is drawn as the bare canvas, with a message on stderr once.
void draw_image(SDL_Renderer* renderer, const Image& image, const ViewTransform& view);

}  // namespace vimg::player_app
