// The painter core of the PNG picture (storage/picture.cpp): pixel spans, edge coverage, the
// band-by-band Painter with its integer blend, row blending and the stripe opacity of surfaces.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "storage/palette.hpp"
#include "storage/picture.hpp"
#include "storage/raster.hpp"

// Everything is drawn in pixel units: X = x_mm * scale, pixel px covers [px, px + 1) and is sampled
// at its centre px + 0.5. A pixel's coverage is clamp(0.5 - d, 0, 1) for the signed distance d (in
// pixels, negative inside) from its centre to the shape's edge: one pixel of ramp across the edge.
// Each shape is drawn row by row over the pixels its ramp can reach, found analytically; pixels
// fully inside are not measured. Polygons are filled by scanlines: exact area coverage per pixel
// from the edges crossing the row (even-odd rule), in time proportional to the pixels and to the
// edges' heights in rows, never to pixels times points.
namespace vimg::picture_detail {

using palette::Rgb8;

// pixel_span, coverage_of and inner_run run once per row or per pixel: inline in every shape's file.

// The pixels whose centres lie strictly inside (lo, hi), clamped to [0, limit): [first, last].
// False when there are none (also for NaN bounds).
inline bool pixel_span(double lo, double hi, int limit, int& first, int& last) {
  if (!(lo < hi) || !(hi > 0.5) || !(lo < limit - 0.5)) return false;
  const double f = std::max(std::ceil(lo - 0.5), 0.0);
  const double l = std::min(std::floor(hi - 0.5), static_cast<double>(limit - 1));
  if (!(f <= l)) return false;
  first = static_cast<int>(f);
  last = static_cast<int>(l);
  return true;
}

inline float coverage_of(double d) { return static_cast<float>(std::clamp(0.5 - d, 0.0, 1.0)); }

// The pixels of [x0, x1] whose centres lie in the closed interval [lo, hi]: [i0, i1] (i0 > i1 when
// none). The shapes use it for the run of pixels they cover fully.
inline void inner_run(double lo, double hi, int x0, int x1, int& i0, int& i1) {
  i0 = x1 + 1;
  i1 = x1;
  if (!(lo <= hi)) return;
  const double f = std::ceil(lo - 0.5), l = std::floor(hi - 0.5);
  if (!(f <= l) || l < x0 || f > x1) return;
  i0 = static_cast<int>(std::max(f, static_cast<double>(x0)));  // clamped before the cast: f and l may be
  i1 = static_cast<int>(std::min(l, static_cast<double>(x1)));  // far outside int (a dot of radius 1e77)
}

// Draws into one band of rows at a time (set_band): every shape is drawn band by band, in paint
// order within each band, so the pixels being blended stay in the cache (a 3000 px wide picture
// has 9 kB rows; a shape drawn over the whole canvas at once touches a new cache line per row).
// The band's rows may sit anywhere (the whole picture, or one band's scanlines of a PNG).
// Threads: one Painter per thread; painters of different bands may run at once.
class Painter {
 public:
  Painter(int width, int height, double scale, PictureWork& work)
      : width_(width), height_(height), scale_(scale), work_(work), row_end_(height) {}

  // Rows [row_begin, row_end) of the picture, the first at `first_row`, `stride` bytes apart.
  void set_band(int row_begin, int row_end, std::uint8_t* first_row, std::size_t stride) {
    row_begin_ = row_begin;
    row_end_ = row_end;
    first_row_ = first_row;
    stride_ = stride;
  }
  int row_begin() const { return row_begin_; }
  int row_end() const { return row_end_; }
  // The rows of the current band whose centres lie strictly inside (lo, hi).
  bool rows(double lo, double hi, int& first, int& last) const {
    if (!pixel_span(lo, hi, height_, first, last)) return false;
    first = std::max(first, row_begin_);
    last = std::min(last, row_end_ - 1);
    return first <= last;
  }
  int width() const { return width_; }
  int height() const { return height_; }
  double scale() const { return scale_; }
  PictureWork& work() { return work_; }
  // Row `py` of the current band: 3 * width() bytes of RGB.
  std::uint8_t* row(int py) { return first_row_ + static_cast<std::size_t>(py - row_begin_) * stride_; }
  // Working memory reused from one shape to the next.
  std::vector<double>& scratch() { return scratch_; }

  // Blends colour c at opacity a (0..1) into the pixel at p, in integers: the opacity in 1/256
  // steps, each channel p + round((c - p) a) (exactly c at a = 1).
  static void blend(std::uint8_t* p, const Rgb8& c, float a) {
    if (!(a > 0.0f)) return;
    const int a8 = a >= 1.0f ? 256 : static_cast<int>(a * 256.0f + 0.5f);
    const auto channel = [a8](std::uint8_t& v, std::uint8_t to) {
      v = static_cast<std::uint8_t>(v + (((to - v) * a8 + 128) >> 8));
    };
    channel(p[0], c.r);
    channel(p[1], c.g);
    channel(p[2], c.b);
  }

 private:
  int width_;
  int height_;
  double scale_;
  PictureWork& work_;
  int row_begin_ = 0;
  int row_end_;
  std::uint8_t* first_row_ = nullptr;
  std::size_t stride_ = 0;
  std::vector<double> scratch_;
};

// Blends one row [x0, x1]: pixels in [i0, i1] fully covered, the others by edge(px); the opacity
// of pixel px is alpha(px).
template <class Edge, class Alpha>
void blend_row(std::uint8_t* row, int x0, int x1, int i0, int i1, const Rgb8& colour, Edge edge, Alpha alpha) {
  const int left_end = std::min(i0, x1 + 1);
  for (int px = x0; px < left_end; ++px) Painter::blend(row + 3 * px, colour, edge(px) * alpha(px));
  for (int px = i0; px <= i1; ++px) Painter::blend(row + 3 * px, colour, alpha(px));
  for (int px = std::max(i1 + 1, left_end); px <= x1; ++px) Painter::blend(row + 3 * px, colour, edge(px) * alpha(px));
}

// Opacity per pixel column of a surface's stripes across x (palette::surface_opacity).
class StripeAlpha {
 public:
  StripeAlpha(const Surface& s, double scale, int first, int last) : first_(first) {
    alpha_.resize(static_cast<std::size_t>(last - first + 1));
    for (int px = first; px <= last; ++px) {
      alpha_[static_cast<std::size_t>(px - first)] = static_cast<float>(palette::surface_opacity(s, (px + 0.5) / scale));
    }
  }
  float operator()(int px) const { return alpha_[static_cast<std::size_t>(px - first_)]; }

 private:
  int first_;
  std::vector<float> alpha_;
};

}  // namespace vimg::picture_detail
