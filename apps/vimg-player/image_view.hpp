#pragma once
// Draws a vibrotactile image at true physical size: `px_per_mm` screen pixels per millimetre,
// the canvas's top-left corner at `origin_px`. DOTs are discs, LINEs bands of their width,
// SURFACEs filled shapes striped at their spatial period.
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

void draw_image(SDL_Renderer* renderer, const Image& image, const ViewTransform& view);

}  // namespace vimg::player_app
