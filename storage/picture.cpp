#include "storage/picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

constexpr int kBandRows = 64;

}  // namespace

std::optional<std::string> picture_size(const Image& image, double scale_px_per_mm, PictureSize& size) {
  if (!std::isfinite(scale_px_per_mm) || scale_px_per_mm <= 0.0) {
    return "the PNG scale must be a finite number of pixels per mm > 0, got " + format_decimal(scale_px_per_mm);
  }
  const double w = std::max(1.0, std::ceil(image.width_mm * scale_px_per_mm));
  const double h = std::max(1.0, std::ceil(image.height_mm * scale_px_per_mm));
  if (!(w * h <= kMaxPngPixels)) {
    return "a PNG of " + format_decimal(w) + " x " + format_decimal(h) + " pixels exceeds the limit of " +
           format_decimal(kMaxPngPixels) + " pixels; use a smaller scale (limit " + format_decimal(kMaxPngPixels) + ")";
  }
  size.width_px = static_cast<int>(w);
  size.height_px = static_cast<int>(h);
  return std::nullopt;
}

std::optional<std::string> draw_picture(const Image& image, double scale_px_per_mm, RgbRaster& raster,
                                        PictureWork* work) {
  PictureSize size;
  if (auto error = picture_size(image, scale_px_per_mm, size)) return error;
  raster.width = size.width_px;
  raster.height = size.height_px;
  raster.rgb.assign(static_cast<std::size_t>(size.width_px) * static_cast<std::size_t>(size.height_px) * 3,
                    palette::kBackground.r);
  static_assert(palette::kBackground.r == palette::kBackground.g && palette::kBackground.g == palette::kBackground.b,
                "one fill value");
  PictureWork unused;
  Painter painter(raster, scale_px_per_mm, work != nullptr ? *work : unused);
  std::vector<Item> items;
  collect(image.children, scale_px_per_mm, items);
  // Items whose rows miss the canvas (or are not numbers) are never drawn.
  std::erase_if(items, [&](const Item& item) {
    return !(item.bottom_px >= 0.0) || !(item.top_px <= raster.height) || !(item.top_px <= item.bottom_px);
  });
  // Each band's items in paint order, found once (not by testing every item in every band).
  const std::size_t bands = static_cast<std::size_t>((raster.height + kBandRows - 1) / kBandRows);
  std::vector<std::uint32_t> count(bands + 1, 0);
  const auto band_range = [&](const Item& item, std::size_t& first, std::size_t& last) {
    // A band [b, b + kBandRows) is visited when top_px <= b + kBandRows and bottom_px >= b.
    const double lo = std::floor((item.top_px - kBandRows) / kBandRows);
    const double hi = std::floor(item.bottom_px / kBandRows);
    first = static_cast<std::size_t>(std::clamp(lo, 0.0, static_cast<double>(bands - 1)));
    last = static_cast<std::size_t>(std::clamp(hi, 0.0, static_cast<double>(bands - 1)));
  };
  for (const Item& item : items) {
    std::size_t first = 0, last = 0;
    band_range(item, first, last);
    for (std::size_t b = first; b <= last; ++b) ++count[b + 1];
  }
  for (std::size_t b = 0; b < bands; ++b) count[b + 1] += count[b];
  std::vector<const Element*> by_band(count[bands]);
  std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
  for (const Item& item : items) {
    std::size_t first = 0, last = 0;
    band_range(item, first, last);
    for (std::size_t b = first; b <= last; ++b) by_band[fill[b]++] = item.element;
  }
  for (std::size_t b = 0; b < bands; ++b) {
    const int band = static_cast<int>(b) * kBandRows;
    painter.set_band(band, std::min(raster.height, band + kBandRows));
    for (std::uint32_t i = count[b]; i < count[b + 1]; ++i) draw_item(painter, *by_band[i]);
  }
  return std::nullopt;
}

}  // namespace vimg
