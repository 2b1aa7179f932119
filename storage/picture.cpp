#include "storage/picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"

namespace vimg {

namespace {

// Euclidean length without std::hypot's care for overflow: a distance that overflows to infinity
// only means "far away", which draws nothing.
inline double length(double dx, double dy) { return std::sqrt(dx * dx + dy * dy); }

struct Rgb {
  double r, g, b;
};

// Canvas and colours (0..255).
constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kDotColour{25, 25, 35};
constexpr Rgb kLowFrequencyColour{240, 140, 0};    // 20 Hz and below: orange
constexpr Rgb kMidFrequencyColour{220, 30, 90};    // ~140 Hz (geometric middle): crimson
constexpr Rgb kHighFrequencyColour{110, 40, 200};  // 1000 Hz: violet
constexpr Rgb kSurfaceColour{20, 120, 150};

// A shape as a signed distance (mm, negative inside) over a bounding box.
struct Box {
  double min_x, min_y, max_x, max_y;
};

class Painter {
 public:
  Painter(RgbRaster& raster, double scale) : raster_(raster), scale_(scale) {}

  // Blends colour(x, y) with opacity(x, y) * coverage over every pixel near the shape.
  template <class Distance, class Colour>
  void fill(const Box& box, Distance distance, Colour colour) {
    const double pad = 1.0 / scale_;
    const int x0 = clamp_px(std::floor((box.min_x - pad) * scale_), raster_.width);
    const int x1 = clamp_px(std::ceil((box.max_x + pad) * scale_), raster_.width);
    const int y0 = clamp_px(std::floor((box.min_y - pad) * scale_), raster_.height);
    const int y1 = clamp_px(std::ceil((box.max_y + pad) * scale_), raster_.height);
    for (int py = y0; py < y1; ++py) {
      const double y = (py + 0.5) / scale_;
      for (int px = x0; px < x1; ++px) {
        const double x = (px + 0.5) / scale_;
        const double coverage = std::clamp(0.5 - distance(x, y) * scale_, 0.0, 1.0);
        if (coverage <= 0.0) continue;
        double alpha = 1.0;
        const Rgb c = colour(x, y, alpha);
        blend(px, py, c, coverage * alpha);
      }
    }
  }

 private:
  static int clamp_px(double v, int limit) {
    if (!(v > 0.0)) return 0;
    return v >= limit ? limit : static_cast<int>(v);
  }

  void blend(int px, int py, const Rgb& c, double alpha) {
    std::uint8_t* p = raster_.pixel(px, py);
    const double channels[3] = {c.r, c.g, c.b};
    for (int i = 0; i < 3; ++i) {
      const double v = p[i] * (1.0 - alpha) + channels[i] * alpha;
      p[i] = static_cast<std::uint8_t>(std::clamp(v + 0.5, 0.0, 255.0));
    }
  }

  RgbRaster& raster_;
  double scale_;
};

double segment_distance(double x, double y, const Line& l) {
  const double dx = l.x2_mm - l.x1_mm;
  const double dy = l.y2_mm - l.y1_mm;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((x - l.x1_mm) * dx + (y - l.y1_mm) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return length(x - (l.x1_mm + t * dx), y - (l.y1_mm + t * dy));
}

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

// Pattern height in [0, 1] at phase u (in periods).
double pattern_value(SurfacePattern pattern, double u) {
  const double frac = u - std::floor(u);
  switch (pattern) {
    case SurfacePattern::sine: return 0.5 + 0.5 * std::sin(2.0 * std::numbers::pi * u);
    case SurfacePattern::square: return frac < 0.5 ? 1.0 : 0.0;
    case SurfacePattern::triangle: return frac < 0.5 ? 2.0 * frac : 2.0 - 2.0 * frac;
  }
  return 0.0;
}

double polygon_distance(double x, double y, const std::vector<Point2Mm>& pts) {
  double best = INFINITY;
  bool inside = false;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const Point2Mm& a = pts[j];
    const Point2Mm& b = pts[i];
    Line edge;
    edge.x1_mm = a.x_mm;
    edge.y1_mm = a.y_mm;
    edge.x2_mm = b.x_mm;
    edge.y2_mm = b.y_mm;
    best = std::min(best, segment_distance(x, y, edge));
    if ((a.y_mm > y) != (b.y_mm > y) && x < a.x_mm + (y - a.y_mm) * (b.x_mm - a.x_mm) / (b.y_mm - a.y_mm)) {
      inside = !inside;
    }
  }
  return inside ? -best : best;
}

void draw_surface(Painter& painter, const Surface& s) {
  const auto colour = [&s](double x, double, double& alpha) {
    const double v = pattern_value(s.pattern, x / s.period_mm);
    alpha = (0.25 + 0.75 * s.gain) * (0.3 + 0.7 * v);
    return kSurfaceColour;
  };
  switch (s.shape) {
    case SurfaceShape::rect: {
      const double cx = s.x_mm + s.width_mm / 2.0;
      const double cy = s.y_mm + s.height_mm / 2.0;
      const auto distance = [&](double x, double y) {
        const double qx = std::abs(x - cx) - s.width_mm / 2.0;
        const double qy = std::abs(y - cy) - s.height_mm / 2.0;
        return length(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
      };
      painter.fill({s.x_mm, s.y_mm, s.x_mm + s.width_mm, s.y_mm + s.height_mm}, distance, colour);
      break;
    }
    case SurfaceShape::ellipse: {
      const auto distance = [&](double x, double y) {
        const double u = (x - s.cx_mm) / s.rx_mm;
        const double v = (y - s.cy_mm) / s.ry_mm;
        const double k = length(u, v);
        if (k == 0.0) return -std::min(s.rx_mm, s.ry_mm);
        // First-order distance: (k - 1) / |grad k|.
        const double grad = length(u / s.rx_mm, v / s.ry_mm) / k;
        return (k - 1.0) / grad;
      };
      painter.fill({s.cx_mm - s.rx_mm, s.cy_mm - s.ry_mm, s.cx_mm + s.rx_mm, s.cy_mm + s.ry_mm}, distance, colour);
      break;
    }
    case SurfaceShape::polygon: {
      if (s.points.size() < 3) return;
      Box box{s.points[0].x_mm, s.points[0].y_mm, s.points[0].x_mm, s.points[0].y_mm};
      for (const auto& p : s.points) {
        box = {std::min(box.min_x, p.x_mm), std::min(box.min_y, p.y_mm), std::max(box.max_x, p.x_mm),
               std::max(box.max_y, p.y_mm)};
      }
      painter.fill(box, [&](double x, double y) { return polygon_distance(x, y, s.points); }, colour);
      break;
    }
  }
}

void draw_line(Painter& painter, const Line& l) {
  const double half = l.width_mm / 2.0;
  // Colour by frequency on a log scale from 20 Hz to 1000 Hz: orange, crimson, violet.
  const double t = std::clamp(std::log(std::max(l.frequency_hz, 20.0) / 20.0) / std::log(50.0), 0.0, 1.0);
  const Rgb base = t < 0.5 ? mix(kLowFrequencyColour, kMidFrequencyColour, 2.0 * t)
                           : mix(kMidFrequencyColour, kHighFrequencyColour, 2.0 * t - 1.0);
  // Ripple along the stroke: 2 mm wavelength at 175 Hz, inversely proportional to frequency.
  const double ripple_mm = 350.0 / l.frequency_hz;
  const double dx = l.x2_mm - l.x1_mm;
  const double dy = l.y2_mm - l.y1_mm;
  const double stroke_mm = length(dx, dy);
  const auto colour = [&](double x, double y, double& alpha) {
    const double along = stroke_mm > 0.0 ? ((x - l.x1_mm) * dx + (y - l.y1_mm) * dy) / stroke_mm : 0.0;
    const double ripple = 0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * along / ripple_mm);
    alpha = (0.35 + 0.65 * l.gain) * (0.7 + 0.3 * ripple);
    return base;
  };
  painter.fill({std::min(l.x1_mm, l.x2_mm) - half, std::min(l.y1_mm, l.y2_mm) - half,
                std::max(l.x1_mm, l.x2_mm) + half, std::max(l.y1_mm, l.y2_mm) + half},
               [&](double x, double y) { return segment_distance(x, y, l) - half; }, colour);
}

void draw_dot(Painter& painter, const Dot& d) {
  const auto colour = [&d](double, double, double& alpha) {
    alpha = 0.35 + 0.65 * d.gain;
    return kDotColour;
  };
  painter.fill({d.x_mm - d.radius_mm, d.y_mm - d.radius_mm, d.x_mm + d.radius_mm, d.y_mm + d.radius_mm},
               [&d](double x, double y) { return length(x - d.x_mm, y - d.y_mm) - d.radius_mm; }, colour);
}

void draw_elements(Painter& painter, const std::vector<Element>& elements) {
  for (const Element& e : elements) {
    if (const auto* d = std::get_if<Dot>(&e.body)) {
      draw_dot(painter, *d);
    } else if (const auto* l = std::get_if<Line>(&e.body)) {
      draw_line(painter, *l);
    } else if (const auto* s = std::get_if<Surface>(&e.body)) {
      draw_surface(painter, *s);
    } else if (const auto* g = std::get_if<Group>(&e.body)) {
      draw_elements(painter, g->children);
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
    return "a PNG of " + format_decimal(w) + " x " + format_decimal(h) + " pixels exceeds the limit of " +
           format_decimal(kMaxPngPixels) + " pixels; use a smaller scale";
  }
  size.width_px = static_cast<int>(w);
  size.height_px = static_cast<int>(h);
  return std::nullopt;
}

std::optional<std::string> draw_picture(const Image& image, double scale_px_per_mm, RgbRaster& raster) {
  PictureSize size;
  if (auto error = picture_size(image, scale_px_per_mm, size)) return error;
  raster.width = size.width_px;
  raster.height = size.height_px;
  raster.rgb.assign(static_cast<std::size_t>(size.width_px) * static_cast<std::size_t>(size.height_px) * 3, 0);
  for (std::size_t i = 0; i < raster.rgb.size(); i += 3) {
    raster.rgb[i] = static_cast<std::uint8_t>(kBackground.r);
    raster.rgb[i + 1] = static_cast<std::uint8_t>(kBackground.g);
    raster.rgb[i + 2] = static_cast<std::uint8_t>(kBackground.b);
  }
  Painter painter(raster, scale_px_per_mm);
  draw_elements(painter, image.children);
  return std::nullopt;
}

}  // namespace vimg
