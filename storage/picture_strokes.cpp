// The PNG picture's strokes: dots (filled discs) and lines (capsules clipped to the canvas, with
// a ripple along them from a cosine table).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "storage/palette.hpp"
#include "storage/picture_painter.hpp"
#include "storage/picture_shapes.hpp"

namespace vimg::picture_detail {

namespace {

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

}  // namespace

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

namespace {

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

}  // namespace

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

}  // namespace vimg::picture_detail
