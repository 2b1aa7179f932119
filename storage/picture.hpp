#pragma once
// The picture of a vibroimage that a PNG shows (spec section 2, docs/format-png.md "PNG rendering"):
// white canvas, anti-aliased primitives in paint order. Dots are dark filled discs, lines are
// stroked capsules coloured by frequency with a ripple whose wavelength shrinks as frequency
// grows, surfaces are filled with stripes of their pattern at their period.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

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

// The picture cut into bands of kRows rows, each drawn on its own, so that an encoder can draw and
// compress several bands at once (storage/png_encode.cpp). The primitives each band may touch are
// found once, in paint order. The image must outlive it.
// Threads: after construction it is read-only; draw_band() may run on several threads at once.
class PictureBands {
 public:
  static constexpr int kRows = 64;

  // error() says why when the scale or the size is not acceptable; there are no bands then.
  PictureBands(const Image& image, double scale_px_per_mm);

  const std::optional<std::string>& error() const { return error_; }
  PictureSize size() const { return size_; }
  int band_count() const { return static_cast<int>(first_of_band_.size()) - 1; }
  // The picture rows of band `band`: [band * kRows, band * kRows + rows_in_band(band)).
  int rows_in_band(int band) const;

  // Draws band `band` into its rows: the first at `first_row`, `stride` bytes apart, 3 * width
  // bytes of RGB each. The rows are filled with the background first. Adds to `work`.
  void draw_band(int band, std::uint8_t* first_row, std::size_t stride, PictureWork& work) const;

 private:
  double scale_;
  PictureSize size_;
  std::optional<std::string> error_;
  std::vector<std::uint32_t> first_of_band_;  // band b draws by_band_[first_of_band_[b] .. first_of_band_[b+1])
  std::vector<const Element*> by_band_;
};

// Draws the image. Returns an error message when the scale or the size is not acceptable.
std::optional<std::string> draw_picture(const Image& image, double scale_px_per_mm, RgbRaster& raster,
                                        PictureWork* work = nullptr);

}  // namespace vimg
