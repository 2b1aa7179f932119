#pragma once
// The picture of a vibroimage that a PNG shows (spec section 2, docs/format.md "PNG rendering"):
// white canvas, anti-aliased primitives in paint order. Dots are dark filled discs, lines are
// stroked capsules coloured by frequency with a ripple whose wavelength shrinks as frequency
// grows, surfaces are filled with stripes of their pattern at their period.
#include <cstdint>
#include <optional>
#include <string>

#include "primitives/image.hpp"
#include "storage/raster.hpp"

namespace vimg {

// The picture size in pixels for a canvas at `scale_px_per_mm`: ceil(size_mm * scale), at least 1.
struct PictureSize {
  int width_px = 0;
  int height_px = 0;
};

// Checks the scale (finite, > 0) and the pixel count limit (kMaxPngPixels); returns an error or the size.
std::optional<std::string> picture_size(const Image& image, double scale_px_per_mm, PictureSize& size);

// The work a drawing did, counted (never timed) so that tests can check how it grows.
struct PictureWork {
  std::uint64_t pixels = 0;      // pixels whose coverage was computed
  std::uint64_t edge_steps = 0;  // polygon edges visited (per pixel or per pixel row)
};

// Draws the image. Returns an error message when the scale or the size is not acceptable.
std::optional<std::string> draw_picture(const Image& image, double scale_px_per_mm, RgbRaster& raster,
                                        PictureWork* work = nullptr);

}  // namespace vimg
