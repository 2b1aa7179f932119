#include "storage/picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "storage/limits.hpp"
#include "storage/number_text.hpp"
#include "storage/palette.hpp"

// Everything is drawn in pixel units: X = x_mm * scale, pixel px covers [px, px + 1) and is sampled
// at its centre px + 0.5. A pixel's coverage is clamp(0.5 - d, 0, 1) for the signed distance d (in
// pixels, negative inside) from its centre to the shape's edge: one pixel of ramp across the edge.
// Each shape is drawn row by row over the pixels its ramp can reach, found analytically; pixels
// fully inside are not measured. Polygons are filled by scanlines: exact area coverage per pixel
// from the edges crossing the row (even-odd rule), in time proportional to the pixels and to the
// edges' heights in rows, never to pixels times points.
namespace vimg {

namespace {

using palette::Rgb8;
// cos(2 pi u) for u in periods, from a table: 4096 steps a period, far below one colour level.
class CosTable {
 public:
  CosTable() {
    for (std::size_t i = 0; i < kSize; ++i) values_[i] = static_cast<float>(std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / kSize));
  }
  // u in periods, |u| < 2^40 (callers reduce their phases to [0, 1) first).
  float operator()(double u) const {
    return values_[static_cast<std::size_t>(static_cast<std::int64_t>(u * kSize)) & (kSize - 1)];
  }

 private:
  static constexpr std::size_t kSize = 4096;
  std::array<float, kSize> values_{};
};

const CosTable& cos_table() {
  static const CosTable table;
  return table;
}

// The pixels whose centres lie strictly inside (lo, hi), clamped to [0, limit): [first, last].
// False when there are none (also for NaN bounds).
bool pixel_span(double lo, double hi, int limit, int& first, int& last) {
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
void inner_run(double lo, double hi, int x0, int x1, int& i0, int& i1) {
  i0 = x1 + 1;
  i1 = x1;
  if (!(lo <= hi)) return;
  const double f = std::ceil(lo - 0.5), l = std::floor(hi - 0.5);
  if (!(f <= l) || l < x0 || f > x1) return;
  i0 = std::max(x0, static_cast<int>(f));
  i1 = std::min(x1, static_cast<int>(l));
}

// Blends one row [x0, x1]: pixels in [i0, i1] fully covered, the others by edge(px); the opacity
// of pixel px is alpha(px).

// Draws into one band of rows at a time (set_band): every shape is drawn band by band, in paint
// order within each band, so the pixels being blended stay in the cache (a 3000 px wide picture
// has 9 kB rows; a shape drawn over the whole canvas at once touches a new cache line per row).
class Painter {
 public:
  Painter(RgbRaster& raster, double scale, PictureWork& work)
      : raster_(raster), scale_(scale), work_(work), row_end_(raster.height) {}

  void set_band(int row_begin, int row_end) {
    row_begin_ = row_begin;
    row_end_ = row_end;
  }
  int row_begin() const { return row_begin_; }
  int row_end() const { return row_end_; }
  // The rows of the current band whose centres lie strictly inside (lo, hi).
  bool rows(double lo, double hi, int& first, int& last) const {
    if (!pixel_span(lo, hi, raster_.height, first, last)) return false;
    first = std::max(first, row_begin_);
    last = std::min(last, row_end_ - 1);
    return first <= last;
  }
  int width() const { return raster_.width; }
  int height() const { return raster_.height; }
  double scale() const { return scale_; }
  PictureWork& work() { return work_; }
  std::uint8_t* row(int py) { return raster_.pixel(0, py); }
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
  RgbRaster& raster_;
  double scale_;
  PictureWork& work_;
  int row_begin_ = 0;
  int row_end_;
  std::vector<double> scratch_;
};

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

// --- dots ------------------------------------------------------------------------------------------

void draw_dot(Painter& painter, const Dot& d) {
  const double s = painter.scale();
  const double cx = d.x_mm * s, cy = d.y_mm * s, r = d.radius_mm * s;
  const auto alpha = static_cast<float>(palette::stroke_opacity(d.gain));
  const double outer = r + 0.5, inner = r - 0.5;
  int y0 = 0, y1 = 0;
  if (!painter.rows(cy - outer, cy + outer, y0, y1)) return;
  for (int py = y0; py <= y1; ++py) {
    const double dy = py + 0.5 - cy;
    const double out2 = outer * outer - dy * dy;
    if (!(out2 > 0.0)) continue;
    const double half_out = std::sqrt(out2);
    int x0 = 0, x1 = 0;
    if (!pixel_span(cx - half_out, cx + half_out, painter.width(), x0, x1)) continue;
    const double in2 = inner > 0.0 ? inner * inner - dy * dy : -1.0;
    const double half_in = in2 > 0.0 ? std::sqrt(in2) : -1.0;
    int i0 = 0, i1 = 0;
    inner_run(cx - half_in, cx + half_in, x0, x1, i0, i1);
    painter.work().pixels += static_cast<std::uint64_t>(x1 - x0 + 1);
    blend_row(painter.row(py), x0, x1, i0, i1, palette::kDot,
              [&](int px) {
                const double dx = px + 0.5 - cx;
                return coverage_of(std::sqrt(dx * dx + dy * dy) - r);
              },
              [alpha](int) { return alpha; });
  }
}

// --- lines -----------------------------------------------------------------------------------------

// Clips the segment (x1,y1)-(x2,y2) to the box [lo_x, hi_x] x [lo_y, hi_y] (Liang-Barsky) in long
// double, where coordinates near the largest double cannot overflow. Returns false when nothing is
// left; t0 is the parameter of the clipped start.
bool clip_segment(long double& x1, long double& y1, long double& x2, long double& y2, long double lo_x,
                  long double hi_x, long double lo_y, long double hi_y, long double& t0) {
  const long double dx = x2 - x1, dy = y2 - y1;
  long double t_in = 0.0L, t_out = 1.0L;
  const auto edge = [&](long double p, long double q) {  // p t <= q
    if (p == 0.0L) return q >= 0.0L;
    const long double t = q / p;
    if (p < 0.0L) t_in = std::max(t_in, t);
    else t_out = std::min(t_out, t);
    return t_in <= t_out;
  };
  if (!edge(-dx, x1 - lo_x) || !edge(dx, hi_x - x1) || !edge(-dy, y1 - lo_y) || !edge(dy, hi_y - y1)) return false;
  const long double sx = x1, sy = y1;
  x1 = sx + t_in * dx;
  y1 = sy + t_in * dy;
  x2 = sx + t_out * dx;
  y2 = sy + t_out * dy;
  t0 = t_in;
  return true;
}

// The open interval of X where a horizontal line at height y is closer than `radius` to the
// segment a-b (a capsule is convex: the union of its end discs and its strip is one interval).
bool capsule_span(double ax, double ay, double bx, double by, double radius, double y, double& lo, double& hi) {
  lo = INFINITY;
  hi = -INFINITY;
  if (!(radius > 0.0)) return false;
  const auto disc = [&](double cx, double cy) {
    const double h2 = radius * radius - (y - cy) * (y - cy);
    if (h2 <= 0.0) return;
    const double h = std::sqrt(h2);
    lo = std::min(lo, cx - h);
    hi = std::max(hi, cx + h);
  };
  disc(ax, ay);
  disc(bx, by);
  const double dx = bx - ax, dy = by - ay;
  const double length = std::sqrt(dx * dx + dy * dy);
  if (length > 0.0) {
    const double ux = dx / length, uy = dy / length;
    // Perpendicular distance n.(p - a) with n = (-uy, ux), and position along u.(p - a) in [0, length].
    double s_lo = -INFINITY, s_hi = INFINITY;
    const auto within = [&](double k, double c, double lower, double upper) {  // lower < k X + c < upper
      if (k == 0.0) {
        if (!(c > lower && c < upper)) s_hi = -INFINITY;
        return;
      }
      double a = (lower - c) / k, b = (upper - c) / k;
      if (a > b) std::swap(a, b);
      s_lo = std::max(s_lo, a);
      s_hi = std::min(s_hi, b);
    };
    within(-uy, ux * (y - ay) + uy * ax, -radius, radius);
    within(ux, uy * (y - ay) - ux * ax, 0.0, length);
    if (s_lo < s_hi) {
      lo = std::min(lo, s_lo);
      hi = std::max(hi, s_hi);
    }
  }
  return lo < hi;
}

void draw_line(Painter& painter, const Line& l) {
  const double s = painter.scale();
  const Rgb8 base = palette::line_colour(l.frequency_hz);
  const double base_alpha = palette::stroke_opacity(l.gain);
  // Ripple along the stroke: 2 mm wavelength at 175 Hz, inversely proportional to frequency.
  const double ripple_px = 350.0 / l.frequency_hz * s;
  const double radius = l.width_mm / 2.0 * s;
  const double outer = radius + 0.5, inner = radius - 0.5;

  // The part of the segment that can reach the canvas, in finite pixel coordinates.
  long double ax = static_cast<long double>(l.x1_mm) * s, ay = static_cast<long double>(l.y1_mm) * s;
  long double bx = static_cast<long double>(l.x2_mm) * s, by = static_cast<long double>(l.y2_mm) * s;
  const long double full_length = std::sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
  const long double margin = static_cast<long double>(outer) + 2.0L;
  long double t0 = 0.0L;
  if (!clip_segment(ax, ay, bx, by, -margin, painter.width() + margin, -margin, painter.height() + margin, t0)) return;
  // The ripple keeps its phase from the segment's real start.
  const double phase0 = ripple_px > 0.0 ? static_cast<double>(std::fmod(t0 * full_length, static_cast<long double>(ripple_px)) /
                                                              static_cast<long double>(ripple_px))
                                        : 0.0;
  const double x1 = static_cast<double>(ax), y1 = static_cast<double>(ay);
  const double x2 = static_cast<double>(bx), y2 = static_cast<double>(by);
  const double dx = x2 - x1, dy = y2 - y1;
  const double length2 = dx * dx + dy * dy;
  const double inv_length2 = length2 > 0.0 ? 1.0 / length2 : 0.0;
  const double length = std::sqrt(length2);
  const double ux = length > 0.0 ? dx / length : 0.0, uy = length > 0.0 ? dy / length : 0.0;
  const CosTable& cosine = cos_table();

  int row0 = 0, row1 = 0;
  if (!painter.rows(std::min(y1, y2) - outer, std::max(y1, y2) + outer, row0, row1)) return;
  for (int py = row0; py <= row1; ++py) {
    const double y = py + 0.5;
    double lo = 0, hi = 0;
    if (!capsule_span(x1, y1, x2, y2, outer, y, lo, hi)) continue;
    int c0 = 0, c1 = 0;
    if (!pixel_span(lo, hi, painter.width(), c0, c1)) continue;
    double in_lo = 0, in_hi = 0;
    const bool has_inner = inner > 0.0 && capsule_span(x1, y1, x2, y2, inner, y, in_lo, in_hi);
    int i0 = 0, i1 = 0;
    if (has_inner) inner_run(in_lo, in_hi, c0, c1, i0, i1);
    else inner_run(1.0, 0.0, c0, c1, i0, i1);
    painter.work().pixels += static_cast<std::uint64_t>(c1 - c0 + 1);
    // The ripple's phase (in periods) at pixel px: start + px * step.
    const double start_periods = phase0 + ((c0 + 0.5 - x1) * ux + (y - y1) * uy) / ripple_px;
    const double step_periods = ux / ripple_px;
    const double start = start_periods - std::floor(start_periods);  // whole periods change nothing
    const double step = step_periods - std::floor(step_periods);
    const auto alpha = [&](int px) {
      const float ripple = 0.5f + 0.5f * cosine(start + (px - c0) * step);
      return static_cast<float>(base_alpha) * (0.7f + 0.3f * ripple);
    };
    const auto edge = [&](int px) {
      const double x = px + 0.5;
      const double tt = length2 > 0.0 ? std::clamp(((x - x1) * dx + (y - y1) * dy) * inv_length2, 0.0, 1.0) : 0.0;
      const double ex = x - (x1 + tt * dx), ey = y - (y1 + tt * dy);
      return coverage_of(std::sqrt(ex * ex + ey * ey) - radius);
    };
    blend_row(painter.row(py), c0, c1, i0, i1, base, edge, alpha);
  }
}

// --- rectangles and ellipses ---------------------------------------------------------------------

void draw_rect(Painter& painter, const Surface& s) {
  const double k = painter.scale();
  const double x0 = s.x_mm * k, y0 = s.y_mm * k;
  const double x1 = (s.x_mm + s.width_mm) * k, y1 = (s.y_mm + s.height_mm) * k;
  const double cx = (x0 + x1) / 2.0, cy = (y0 + y1) / 2.0, hx = (x1 - x0) / 2.0, hy = (y1 - y0) / 2.0;
  int r0 = 0, r1 = 0, c0 = 0, c1 = 0;
  if (!painter.rows(y0 - 0.5, y1 + 0.5, r0, r1)) return;
  if (!pixel_span(x0 - 0.5, x1 + 0.5, painter.width(), c0, c1)) return;
  const StripeAlpha alpha(s, k, c0, c1);
  for (int py = r0; py <= r1; ++py) {
    const double qy = std::abs(py + 0.5 - cy) - hy;
    int i0 = 0, i1 = 0;
    if (qy <= -0.5) inner_run(cx - hx + 0.5, cx + hx - 0.5, c0, c1, i0, i1);
    else inner_run(1.0, 0.0, c0, c1, i0, i1);
    painter.work().pixels += static_cast<std::uint64_t>(c1 - c0 + 1);
    blend_row(painter.row(py), c0, c1, i0, i1, palette::kSurface,
              [&](int px) {
                const double qx = std::abs(px + 0.5 - cx) - hx;
                const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
                return coverage_of(std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0));
              },
              alpha);
  }
}

void draw_ellipse(Painter& painter, const Surface& s) {
  const double k = painter.scale();
  const double cx = s.cx_mm * k, cy = s.cy_mm * k, rx = s.rx_mm * k, ry = s.ry_mm * k;
  // The ramp lies between the ellipses with radii 1.5 px smaller and larger; inside the smaller
  // one every pixel is covered.
  const double ox = rx + 1.5, oy = ry + 1.5, ix = rx - 1.5, iy = ry - 1.5;
  int r0 = 0, r1 = 0, c0 = 0, c1 = 0;
  if (!painter.rows(cy - oy, cy + oy, r0, r1)) return;
  if (!pixel_span(cx - ox, cx + ox, painter.width(), c0, c1)) return;
  const StripeAlpha alpha(s, k, c0, c1);
  for (int py = r0; py <= r1; ++py) {
    const double dy = py + 0.5 - cy;
    const double wo = 1.0 - (dy / oy) * (dy / oy);
    if (!(wo > 0.0)) continue;
    const double half_out = ox * std::sqrt(wo);
    int x0 = 0, x1 = 0;
    if (!pixel_span(cx - half_out, cx + half_out, painter.width(), x0, x1)) continue;
    const double wi = ix > 0.0 && iy > 0.0 ? 1.0 - (dy / iy) * (dy / iy) : -1.0;
    const double half_in = wi > 0.0 ? ix * std::sqrt(wi) : -1.0;
    int i0 = 0, i1 = 0;
    inner_run(cx - half_in, cx + half_in, x0, x1, i0, i1);
    painter.work().pixels += static_cast<std::uint64_t>(x1 - x0 + 1);
    const double v = dy / ry;
    blend_row(painter.row(py), x0, x1, i0, i1, palette::kSurface,
              [&](int px) {
                // First-order distance to the ellipse: (k - 1) / |grad k| with k = |(dx/rx, dy/ry)|.
                const double u = (px + 0.5 - cx) / rx;
                const double kk = std::sqrt(u * u + v * v);
                if (!(kk > 0.0)) return 1.0f;
                const double grad = std::sqrt((u / rx) * (u / rx) + (v / ry) * (v / ry)) / kk;
                return coverage_of((kk - 1.0) / grad);
              },
              alpha);
  }
}

// --- polygons --------------------------------------------------------------------------------------

// An edge piece inside the canvas, y0 < y1, with the winding direction of the original edge.
struct Edge {
  double x0, y0, x1, y1;
  double slope;  // dx / dy
  double dir;
};

// Clips one polygon edge to the canvas rows [0, height] and columns [0, width]: what lies left of
// the canvas becomes a vertical piece at x = 0 (it still winds every pixel to its right), what lies
// right of it is dropped (it winds nothing on the canvas, but the winding of the pieces left of it
// then reaches the right border: `to_right` is set).
void add_edge(std::vector<Edge>& edges, long double ax, long double ay, long double bx, long double by, int width,
              int row_begin, int row_end, bool& to_right) {
  if (ay == by) return;
  double dir = 1.0;
  if (ay > by) {
    std::swap(ax, bx);
    std::swap(ay, by);
    dir = -1.0;
  }
  const long double top = std::max(ay, static_cast<long double>(row_begin));
  const long double bottom = std::min(by, static_cast<long double>(row_end));
  if (!(top < bottom)) return;
  const long double slope = (bx - ax) / (by - ay);  // dx per dy, finite in long double
  const auto x_at = [&](long double y) { return ax + (y - ay) * slope; };
  long double xt = x_at(top), xb = x_at(bottom);
  // Split at x = 0 and x = width.
  const long double w = static_cast<long double>(width);
  std::array<long double, 4> ys{top, bottom, top, top};
  std::size_t n = 2;
  for (const long double x_cut : {0.0L, w}) {
    if ((xt - x_cut) * (xb - x_cut) < 0.0L && slope != 0.0L) ys[n++] = ay + (x_cut - ax) / slope;
  }
  // At most four values: an insertion sort (std::sort here trips a false -Warray-bounds of g++ 12
  // at -O2, which the sanitizer presets build with).
  for (std::size_t i = 1; i < n; ++i) {
    for (std::size_t j = i; j > 0 && ys[j] < ys[j - 1]; --j) std::swap(ys[j], ys[j - 1]);
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const long double y0 = ys[i], y1 = ys[i + 1];
    if (!(y0 < y1)) continue;
    long double x0 = x_at(y0), x1 = x_at(y1);
    const long double mid = (x0 + x1) / 2.0L;
    if (mid >= w) {
      to_right = true;
      continue;
    }
    if (mid <= 0.0L) x0 = x1 = 0.0L;
    x0 = std::clamp(x0, 0.0L, w);
    x1 = std::clamp(x1, 0.0L, w);
    const auto e0 = static_cast<double>(x0), e1 = static_cast<double>(x1);
    const auto f0 = static_cast<double>(y0), f1 = static_cast<double>(y1);
    edges.push_back({e0, f0, e1, f1, (e1 - e0) / (f1 - f0), dir});
  }
}

// Adds the signed area of an edge piece within one pixel row to the accumulation buffer: the
// coverage of pixel c is the running sum of acc[0..c] (the piece lies within [y0, y1] of height
// at most 1, x >= 0 and within the row's cells).
void accumulate(double* acc, double xa, double ya, double xb, double yb, double dir) {
  const double d = (yb - ya) * dir;
  const double x0 = std::min(xa, xb), x1 = std::max(xa, xb);
  // x >= 0 here: the integer conversion is the floor (cheaper than std::floor without SSE4.1;
  // a signed conversion is one instruction, an unsigned one is not).
  const auto x0i = static_cast<std::ptrdiff_t>(x0);
  const double x0floor = static_cast<double>(x0i);
  auto x1i = static_cast<std::ptrdiff_t>(x1);
  if (static_cast<double>(x1i) < x1) ++x1i;
  const double x1ceil = static_cast<double>(x1i);
  if (x1i <= x0i + 1) {
    const double xmf = 0.5 * (xa + xb) - x0floor;
    acc[x0i] += d - d * xmf;
    acc[x0i + 1] += d * xmf;
    return;
  }
  const double inv = 1.0 / (x1 - x0);
  const double x0f = x0 - x0floor;
  const double a0 = 0.5 * inv * (1.0 - x0f) * (1.0 - x0f);
  const double x1f = x1 - x1ceil + 1.0;
  const double am = 0.5 * inv * x1f * x1f;
  acc[x0i] += d * a0;
  if (x1i == x0i + 2) {
    acc[x0i + 1] += d * (1.0 - a0 - am);
  } else {
    const double a1 = inv * (1.5 - x0f);
    acc[x0i + 1] += d * (a1 - a0);
    for (std::ptrdiff_t xi = x0i + 2; xi + 1 < x1i; ++xi) acc[xi] += d * inv;
    const double a2 = a1 + static_cast<double>(x1i - x0i - 3) * inv;
    acc[x1i - 1] += d * (1.0 - a2 - am);
  }
  acc[x1i] += d * am;
}

void draw_polygon(Painter& painter, const Surface& s) {
  if (s.points.size() < 3) return;
  const int width = painter.width();
  const long double k = painter.scale();
  // The edges crossing the current band, clipped to it.
  const double band_top_mm = painter.row_begin() / painter.scale(), band_bottom_mm = painter.row_end() / painter.scale();
  std::vector<Edge> edges;
  bool to_right = false;
  for (std::size_t i = 0, j = s.points.size() - 1; i < s.points.size(); j = i++) {
    const Point2Mm& a = s.points[j];
    const Point2Mm& b = s.points[i];
    if (std::max(a.y_mm, b.y_mm) < band_top_mm || std::min(a.y_mm, b.y_mm) > band_bottom_mm) continue;
    add_edge(edges, a.x_mm * k, a.y_mm * k, b.x_mm * k, b.y_mm * k, width, painter.row_begin(), painter.row_end(),
             to_right);
  }
  if (edges.empty()) return;
  double min_x = width, max_x = 0.0, min_y = INFINITY, max_y = 0.0;
  for (const Edge& e : edges) {
    min_x = std::min({min_x, e.x0, e.x1});
    max_x = std::max({max_x, e.x0, e.x1});
    min_y = std::min(min_y, e.y0);
    max_y = std::max(max_y, e.y1);
  }
  const int c0 = static_cast<int>(std::floor(min_x));
  const int c1 = to_right ? width - 1 : std::min(width - 1, static_cast<int>(std::ceil(max_x)));
  const int row0 = std::max(painter.row_begin(), static_cast<int>(std::floor(min_y)));
  const int row1 = std::min(painter.row_end() - 1, static_cast<int>(std::ceil(max_y)));
  if (c0 > c1 || row0 > row1) return;
  // Each edge adds its area to the rows it crosses, edge by edge (its data is read once per
  // band, whatever the number of edges crossing a row); the accumulation rows span the edges'
  // columns, shifted by c0, with room for the cell right of the rightmost edge.
  const std::size_t stride = static_cast<std::size_t>(std::ceil(max_x) - c0) + 2;
  std::vector<double>& acc = painter.scratch();
  acc.assign(stride * static_cast<std::size_t>(row1 - row0 + 1), 0.0);
  const double shift = c0;
  for (const Edge& e : edges) {
    const int first = std::max(row0, static_cast<int>(std::floor(e.y0)));
    const int last = std::min(row1, static_cast<int>(std::ceil(e.y1)) - 1);
    // The piece's ends are within [0, width] (add_edge), so is every point between them; the
    // clamp only absorbs rounding.
    const auto x_at = [&](double y) { return std::clamp(e.x0 + (y - e.y0) * e.slope - shift, 0.0, max_x - shift); };
    const auto piece = [&](int py) {
      const double ya = std::max(e.y0, static_cast<double>(py)), yb = std::min(e.y1, py + 1.0);
      if (ya < yb) accumulate(acc.data() + stride * static_cast<std::size_t>(py - row0), x_at(ya), ya, x_at(yb), yb, e.dir);
    };
    // Rows the piece crosses whole, the common case of long edges: x steps by the slope, and a
    // step within one cell (steep edges) is two additions.
    const int full_first = std::max(first, static_cast<int>(std::ceil(e.y0)));
    const int full_last = std::min(last, static_cast<int>(std::floor(e.y1)) - 1);
    if (full_first > full_last) {
      for (int py = first; py <= last; ++py) piece(py);
    } else {
      for (int py = first; py < full_first; ++py) piece(py);
      double x = x_at(full_first);
      for (int py = full_first; py <= full_last; ++py) {
        const double next = std::clamp(x + e.slope, 0.0, max_x - shift);
        double* cells = acc.data() + stride * static_cast<std::size_t>(py - row0);
        const auto i = static_cast<std::ptrdiff_t>(std::min(x, next));
        if (std::max(x, next) <= static_cast<double>(i + 1)) {
          const double xmf = 0.5 * (x + next) - static_cast<double>(i);
          cells[i] += e.dir - e.dir * xmf;
          cells[i + 1] += e.dir * xmf;
        } else {
          accumulate(cells, x, py, next, py + 1.0, e.dir);
        }
        x = next;
      }
      for (int py = full_last + 1; py <= last; ++py) piece(py);
    }
    painter.work().edge_steps += static_cast<std::uint64_t>(std::max(0, last - first + 1));
  }
  const StripeAlpha alpha(s, painter.scale(), c0, c1);
  const int last_acc = c0 + static_cast<int>(stride) - 1;
  for (int py = row0; py <= row1; ++py) {
    const double* row_acc = acc.data() + stride * static_cast<std::size_t>(py - row0);
    std::uint8_t* row = painter.row(py);
    painter.work().pixels += static_cast<std::uint64_t>(c1 - c0 + 1);
    double winding = 0.0;
    for (int px = c0; px <= c1; ++px) {
      if (px <= last_acc) winding += row_acc[px - c0];
      // Even-odd: the coverage folds the winding area into [0, 1].
      double c = std::abs(winding);
      if (c > 1.0) {
        c = std::fmod(c, 2.0);
        if (c > 1.0) c = 2.0 - c;
      }
      if (c > 1e-6) Painter::blend(row + 3 * px, palette::kSurface, static_cast<float>(c) * alpha(px));
    }
  }
}

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
