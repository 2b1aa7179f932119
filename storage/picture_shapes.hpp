// How each primitive is drawn into the PNG picture's current band: one function a shape, called in
// paint order by draw_picture (storage/picture.cpp).
#pragma once
#include "primitives/image.hpp"
#include "storage/picture_painter.hpp"

namespace vimg::picture_detail {

// Dots and lines (storage/picture_strokes.cpp).
void draw_dot(Painter& painter, const Dot& d);
void draw_line(Painter& painter, const Line& l);

// Rectangles and ellipses (storage/picture_filled.cpp).
void draw_rect(Painter& painter, const Surface& s);
void draw_ellipse(Painter& painter, const Surface& s);

// Polygons, filled by scanlines with the even-odd rule (storage/picture_polygon.cpp).
void draw_polygon(Painter& painter, const Surface& s);

}  // namespace vimg::picture_detail
