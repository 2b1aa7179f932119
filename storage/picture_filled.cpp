// The PNG picture's rectangles and ellipses: filled analytically row by row, with the stripes of
// their surface pattern.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "storage/palette.hpp"
#include "storage/picture_painter.hpp"
#include "storage/picture_shapes.hpp"

namespace vimg::picture_detail {

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

}  // namespace vimg::picture_detail
