// The PNG picture's polygons: edges clipped to the canvas band, their signed areas accumulated per
// pixel row, then a scanline fill with the even-odd rule.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "storage/palette.hpp"
#include "storage/picture_painter.hpp"
#include "storage/picture_shapes.hpp"

namespace vimg::picture_detail {

namespace {

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

}  // namespace

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

}  // namespace vimg::picture_detail
