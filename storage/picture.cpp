#include "storage/picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/palette.hpp"
#include "storage/picture_painter.hpp"
#include "storage/picture_shapes.hpp"

// The paint order: primitives are collected with the rows they may touch, sorted into bands of
// rows, and drawn band by band (storage/picture_painter.hpp) by the functions of
// storage/picture_shapes.hpp.
namespace vimg {

namespace {

using picture_detail::Painter;
using picture_detail::draw_dot;
using picture_detail::draw_ellipse;
using picture_detail::draw_line;
using picture_detail::draw_polygon;
using picture_detail::draw_rect;

// A primitive in paint order with the rows it may touch.
struct Item {
  const Element* element;
  double top_px, bottom_px;
};

void collect(const std::vector<Element>& elements, double s, std::vector<Item>& items) {
  for (const Element& e : elements) {
    if (const auto* d = std::get_if<Dot>(&e.body)) {
      items.push_back({&e, (d->y_mm - d->radius_mm) * s - 1.0, (d->y_mm + d->radius_mm) * s + 1.0});
    } else if (const auto* l = std::get_if<Line>(&e.body)) {
      const double half = l->width_mm / 2.0;
      items.push_back({&e, (std::min(l->y1_mm, l->y2_mm) - half) * s - 1.0, (std::max(l->y1_mm, l->y2_mm) + half) * s + 1.0});
    } else if (const auto* f = std::get_if<Surface>(&e.body)) {
      double top = 0, bottom = 0;
      switch (f->shape) {
        case SurfaceShape::rect: top = f->y_mm; bottom = f->y_mm + f->height_mm; break;
        case SurfaceShape::ellipse: top = f->cy_mm - f->ry_mm; bottom = f->cy_mm + f->ry_mm; break;
        case SurfaceShape::polygon:
          if (f->points.empty()) continue;
          top = bottom = f->points[0].y_mm;
          for (const Point2Mm& p : f->points) {
            top = std::min(top, p.y_mm);
            bottom = std::max(bottom, p.y_mm);
          }
          break;
      }
      items.push_back({&e, top * s - 2.0, bottom * s + 2.0});
    } else if (const auto* g = std::get_if<Group>(&e.body)) {
      collect(g->children, s, items);
    }
  }
}

void draw_item(Painter& painter, const Element& e) {
  if (const auto* d = std::get_if<Dot>(&e.body)) {
    draw_dot(painter, *d);
  } else if (const auto* l = std::get_if<Line>(&e.body)) {
    draw_line(painter, *l);
  } else if (const auto* s = std::get_if<Surface>(&e.body)) {
    switch (s->shape) {
      case SurfaceShape::rect: draw_rect(painter, *s); break;
      case SurfaceShape::ellipse: draw_ellipse(painter, *s); break;
      case SurfaceShape::polygon: draw_polygon(painter, *s); break;
    }
  }
}

}  // namespace

std::optional<std::string> picture_size(const Image& image, double scale_px_per_mm, PictureSize& size) {
  if (!std::isfinite(scale_px_per_mm) || scale_px_per_mm <= 0.0) {
    return "the PNG scale must be a finite number of pixels per mm > 0, got " + format_decimal(scale_px_per_mm);
  }
  const double w = std::max(1.0, std::ceil(image.width_mm * scale_px_per_mm));
  const double h = std::max(1.0, std::ceil(image.height_mm * scale_px_per_mm));
  if (!(w * h <= kMaxPngPixels)) {
    const std::string limit = std::to_string(static_cast<long long>(kMaxPngPixels));
    return "a PNG of " + format_decimal(w) + " x " + format_decimal(h) + " pixels exceeds the limit of " + limit +
           " pixels; use a smaller scale (limit " + limit + ")";
  }
  size.width_px = static_cast<int>(w);
  size.height_px = static_cast<int>(h);
  return std::nullopt;
}

PictureBands::PictureBands(const Image& image, double scale_px_per_mm) : scale_(scale_px_per_mm) {
  error_ = picture_size(image, scale_px_per_mm, size_);
  first_of_band_.assign(1, 0);
  if (error_) return;
  std::vector<Item> items;
  collect(image.children, scale_px_per_mm, items);
  // Items whose rows miss the canvas (or are not numbers) are never drawn.
  const int height = size_.height_px;
  std::erase_if(items, [&](const Item& item) {
    return !(item.bottom_px >= 0.0) || !(item.top_px <= height) || !(item.top_px <= item.bottom_px);
  });
  // Each band's items in paint order, found once (not by testing every item in every band).
  const std::size_t bands = static_cast<std::size_t>((height + kRows - 1) / kRows);
  std::vector<std::uint32_t>& count = first_of_band_;
  count.assign(bands + 1, 0);
  const auto band_range = [&](const Item& item, std::size_t& first, std::size_t& last) {
    // A band [b, b + kRows) is visited when top_px <= b + kRows and bottom_px >= b.
    const double lo = std::floor((item.top_px - kRows) / kRows);
    const double hi = std::floor(item.bottom_px / kRows);
    first = static_cast<std::size_t>(std::clamp(lo, 0.0, static_cast<double>(bands - 1)));
    last = static_cast<std::size_t>(std::clamp(hi, 0.0, static_cast<double>(bands - 1)));
  };
  for (const Item& item : items) {
    std::size_t first = 0, last = 0;
    band_range(item, first, last);
    for (std::size_t b = first; b <= last; ++b) ++count[b + 1];
  }
  for (std::size_t b = 0; b < bands; ++b) count[b + 1] += count[b];
  by_band_.resize(count[bands]);
  std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
  for (const Item& item : items) {
    std::size_t first = 0, last = 0;
    band_range(item, first, last);
    for (std::size_t b = first; b <= last; ++b) by_band_[fill[b]++] = item.element;
  }
}

int PictureBands::rows_in_band(int band) const { return std::min(kRows, size_.height_px - band * kRows); }

void PictureBands::draw_band(int band, std::uint8_t* first_row, std::size_t stride, PictureWork& work) const {
  const int row_begin = band * kRows;
  const int rows = rows_in_band(band);
  const std::size_t row_bytes = static_cast<std::size_t>(size_.width_px) * 3;
  static_assert(palette::kBackground.r == palette::kBackground.g && palette::kBackground.g == palette::kBackground.b,
                "one fill value");
  for (int r = 0; r < rows; ++r) std::memset(first_row + static_cast<std::size_t>(r) * stride, palette::kBackground.r, row_bytes);
  Painter painter(size_.width_px, size_.height_px, scale_, work);
  painter.set_band(row_begin, row_begin + rows, first_row, stride);
  const auto b = static_cast<std::size_t>(band);
  for (std::uint32_t i = first_of_band_[b]; i < first_of_band_[b + 1]; ++i) draw_item(painter, *by_band_[i]);
}

std::optional<std::string> draw_picture(const Image& image, double scale_px_per_mm, RgbRaster& raster,
                                        PictureWork* work) {
  const PictureBands bands(image, scale_px_per_mm);
  if (bands.error()) return bands.error();
  raster.width = bands.size().width_px;
  raster.height = bands.size().height_px;
  raster.rgb.resize(static_cast<std::size_t>(raster.width) * static_cast<std::size_t>(raster.height) * 3);
  PictureWork unused;
  const std::size_t stride = static_cast<std::size_t>(raster.width) * 3;
  for (int b = 0; b < bands.band_count(); ++b) {
    bands.draw_band(b, raster.pixel(0, b * PictureBands::kRows), stride, work != nullptr ? *work : unused);
  }
  return std::nullopt;
}

}  // namespace vimg
