#include "web/wasm/picture_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include "storage/palette.hpp"

namespace vimg {

namespace {

constexpr int kMaxStripeSamples = 2048;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string rgb(const palette::Rgb8& c) {
  return "[" + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + "]";
}

std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

// The x range a surface covers, mm.
std::pair<double, double> x_extent(const Surface& s) {
  switch (s.shape) {
    case SurfaceShape::rect: return {s.x_mm, s.x_mm + s.width_mm};
    case SurfaceShape::ellipse: return {s.cx_mm - s.rx_mm, s.cx_mm + s.rx_mm};
    case SurfaceShape::polygon: break;
  }
  double lo = s.points.empty() ? 0.0 : s.points[0].x_mm;
  double hi = lo;
  for (const auto& p : s.points) {
    lo = std::min(lo, p.x_mm);
    hi = std::max(hi, p.x_mm);
  }
  return {lo, hi};
}

std::string surface_json(const Surface& s) {
  std::string out = "\"kind\":\"surface\",\"color\":" + rgb(palette::kSurface);
  if (s.shape == SurfaceShape::rect) {
    out += ",\"shape\":\"rect\",\"x\":" + num(s.x_mm) + ",\"y\":" + num(s.y_mm) + ",\"w\":" + num(s.width_mm) + ",\"h\":" + num(s.height_mm);
  } else if (s.shape == SurfaceShape::ellipse) {
    out += ",\"shape\":\"ellipse\",\"cx\":" + num(s.cx_mm) + ",\"cy\":" + num(s.cy_mm) + ",\"rx\":" + num(s.rx_mm) + ",\"ry\":" + num(s.ry_mm);
  } else {
    out += ",\"shape\":\"polygon\",\"points\":[";
    for (std::size_t i = 0; i < s.points.size(); ++i) out += (i ? "," : "") + num(s.points[i].x_mm) + "," + num(s.points[i].y_mm);
    out += "]";
  }
  const auto [x0, x1] = x_extent(s);
  const double step = std::max(s.period_mm / 8.0, (x1 - x0) / kMaxStripeSamples);
  out += ",\"stripe_x0\":" + num(x0) + ",\"stripe_step\":" + num(step) + ",\"stripes\":[";
  int n = 0;
  for (double x = x0; x < x1 && n < kMaxStripeSamples; x = x0 + step * ++n) {
    out += (n ? "," : "") + num(palette::surface_opacity(s, x + step / 2.0));
  }
  return out + "]";
}

void flatten(const std::vector<Element>& elements, std::string& out, bool& first) {
  for (const Element& e : elements) {
    std::string item;
    if (const auto* d = std::get_if<Dot>(&e.body)) {
      item = "\"kind\":\"dot\",\"x\":" + num(d->x_mm) + ",\"y\":" + num(d->y_mm) + ",\"r\":" + num(d->radius_mm) +
             ",\"color\":" + rgb(palette::kDot) + ",\"opacity\":" + num(palette::stroke_opacity(d->gain));
    } else if (const auto* l = std::get_if<Line>(&e.body)) {
      item = "\"kind\":\"line\",\"x1\":" + num(l->x1_mm) + ",\"y1\":" + num(l->y1_mm) + ",\"x2\":" + num(l->x2_mm) +
             ",\"y2\":" + num(l->y2_mm) + ",\"width\":" + num(l->width_mm) + ",\"color\":" + rgb(palette::line_colour(l->frequency_hz)) +
             ",\"opacity\":" + num(palette::stroke_opacity(l->gain));
    } else if (const auto* s = std::get_if<Surface>(&e.body)) {
      item = surface_json(*s);
    } else if (const auto* g = std::get_if<Group>(&e.body)) {
      flatten(g->children, out, first);
      continue;
    } else {
      continue;
    }
    out += std::string(first ? "" : ",") + "{\"id\":\"" + escaped(e.id) + "\"," + item + "}";
    first = false;
  }
}

}  // namespace

std::string picture_json(const Image& image) {
  std::string out = "{\"width_mm\":" + num(image.width_mm) + ",\"height_mm\":" + num(image.height_mm) +
                    ",\"background\":" + rgb(palette::kBackground) + ",\"border\":" + rgb(palette::kCanvasBorder) +
                    ",\"highlight\":" + rgb(palette::kHighlight) + ",\"items\":[";
  bool first = true;
  flatten(image.children, out, first);
  return out + "]}";
}

}  // namespace vimg
