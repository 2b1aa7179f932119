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

// Draws the image. The picture is drawn once into a texture and reused while the renderer, the
// image (its address and primitive count) and the scale stay the same; a picture over the PNG
// pixel limit is drawn as the bare canvas, with a message on stderr once.
void draw_image(SDL_Renderer* renderer, const Image& image, const ViewTransform& view);

}  // namespace vimg::player_app
