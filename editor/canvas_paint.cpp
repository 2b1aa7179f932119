// The canvas's picture of the document: the page and its grid, every primitive drawn so that its
// parameters read at a glance (docs/editor-drawing.md, "What you see"), and the selection.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "editor/canvas_cache.hpp"
#include "editor/canvas_view.hpp"
#include "editor/core/polyline_lod.hpp"
#include "editor/playback.hpp"
#include "storage/palette.hpp"

namespace vimg::editor {
namespace {

// The colours of storage/palette.hpp, shared with the PNG picture and the player.
constexpr ImU32 rgb(const palette::Rgb8& c) { return IM_COL32(c.r, c.g, c.b, 255); }
constexpr ImU32 kDotColour = rgb(palette::kDot);
constexpr ImU32 kSurfaceColour = rgb(palette::kSurface);
constexpr ImU32 kHighlight = rgb(palette::kHighlight);
constexpr ImU32 kSelectionColour = rgb(palette::kSelection);
constexpr ImU32 kHandleFill = IM_COL32(255, 255, 255, 255);
ImU32 line_colour(const Line& l) { return rgb(palette::line_colour(l.frequency_hz)); }
int opacity_alpha(double opacity) { return static_cast<int>(std::lround(255.0 * std::clamp(opacity, 0.0, 1.0))); }

ImU32 with_alpha(ImU32 colour, int alpha) { return (colour & 0x00FFFFFFu) | (static_cast<ImU32>(alpha) << 24); }
ImVec2 iv(Point2Px p) { return ImVec2(p.x, p.y); }

// The x-intervals where the horizontal line y crosses into the surface.
void surface_spans(const Surface& s, double y, std::vector<std::pair<double, double>>& spans) {
  spans.clear();
  if (s.shape == SurfaceShape::rect) {
    if (y >= s.y_mm && y <= s.y_mm + s.height_mm) spans.emplace_back(s.x_mm, s.x_mm + s.width_mm);
  } else if (s.shape == SurfaceShape::ellipse) {
    if (s.ry_mm <= 0) return;
    const double v = (y - s.cy_mm) / s.ry_mm;
    if (std::abs(v) <= 1) {
      const double half = s.rx_mm * std::sqrt(1 - v * v);
      spans.emplace_back(s.cx_mm - half, s.cx_mm + half);
    }
  } else {
    std::vector<double> xs;
    const auto& p = s.points;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
      if ((p[i].y_mm > y) != (p[j].y_mm > y)) {
        xs.push_back(p[i].x_mm + (y - p[i].y_mm) * (p[j].x_mm - p[i].x_mm) / (p[j].y_mm - p[i].y_mm));
      }
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2) spans.emplace_back(xs[i], xs[i + 1]);
  }
}

// The y-intervals of the vertical line x inside the surface (stripes run vertically).
void surface_vertical_spans(const Surface& s, double x, std::vector<std::pair<double, double>>& spans) {
  Surface t = s;  // transpose and reuse the horizontal case
  std::swap(t.x_mm, t.y_mm);
  std::swap(t.width_mm, t.height_mm);
  std::swap(t.cx_mm, t.cy_mm);
  std::swap(t.rx_mm, t.ry_mm);
  for (Point2Mm& p : t.points) std::swap(p.x_mm, p.y_mm);
  surface_spans(t, x, spans);
}

}  // namespace

void CanvasView::draw_page(ImDrawList* dl) const {
  const Image& image = doc_.image();
  const Point2Px p0 = view_.to_px({0, 0});
  const Point2Px p1 = view_.to_px({image.width_mm, image.height_mm});
  dl->AddRectFilled(iv(p0), iv(p1), rgb(palette::kBackground));
  const double ppm = view_.px_per_mm();
  const double minor = grid_step_mm(ppm, 8.0);
  const double major = grid_step_mm(ppm, 60.0);
  if (show_grid_) {
    const ImU32 minor_c = IM_COL32(225, 225, 220, 255);
    const ImU32 major_c = IM_COL32(195, 195, 190, 255);
    for (double gx = 0; gx <= image.width_mm + 1e-9; gx += minor) {
      const float px = view_.to_px({gx, 0}).x;
      if (px < canvas_x_ || px > canvas_x_ + canvas_w_) continue;
      const bool is_major = std::abs(std::remainder(gx, major)) < 1e-6;
      dl->AddLine(ImVec2(px, p0.y), ImVec2(px, p1.y), is_major ? major_c : minor_c);
    }
    for (double gy = 0; gy <= image.height_mm + 1e-9; gy += minor) {
      const float py = view_.to_px({0, gy}).y;
      if (py < canvas_y_ || py > canvas_y_ + canvas_h_) continue;
      const bool is_major = std::abs(std::remainder(gy, major)) < 1e-6;
      dl->AddLine(ImVec2(p0.x, py), ImVec2(p1.x, py), is_major ? major_c : minor_c);
    }
  }
  dl->AddRect(iv(p0), iv(p1), rgb(palette::kCanvasBorder));
}

void CanvasView::draw_line(ImDrawList* dl, const Line& l, bool highlighted) const {
  const float ppm = static_cast<float>(view_.px_per_mm());
  const Point2Px a = view_.to_px({l.x1_mm, l.y1_mm});
  const Point2Px b = view_.to_px({l.x2_mm, l.y2_mm});
  const ImU32 col = highlighted ? kHighlight : line_colour(l);
  dl->AddLine(iv(a), iv(b), with_alpha(col, 70), std::max(1.0f, view_.length_px(l.width_mm)));
  // A wave along the segment: one drawn cycle per 1000/f mm, so a higher pitch looks denser.
  const double len = std::hypot(l.x2_mm - l.x1_mm, l.y2_mm - l.y1_mm);
  if (!(len > 0 && len * ppm > 6)) {
    dl->AddLine(iv(a), iv(b), with_alpha(col, 255), 1.5f);
    return;
  }
  const double ux = (l.x2_mm - l.x1_mm) / len, uy = (l.y2_mm - l.y1_mm) / len;
  const double wavelength_mm = std::max(0.5, 1000.0 / std::max(1.0, l.frequency_hz));
  const double amp = l.width_mm * 0.35;
  const int steps = std::clamp(static_cast<int>(len / wavelength_mm * 12), 8, 400);
  ImVec2 prev = iv(a);
  for (int i = 1; i <= steps; ++i) {
    const double t = len * i / steps;
    const double off = amp * std::sin(2 * std::numbers::pi * t / wavelength_mm);
    const ImVec2 cur = iv(view_.to_px({l.x1_mm + ux * t - uy * off, l.y1_mm + uy * t + ux * off}));
    dl->AddLine(prev, cur, with_alpha(col, 255), 1.5f);
    prev = cur;
  }
  if (len * ppm > 40) {
    char label[32];
    std::snprintf(label, sizeof label, "%.0f Hz", l.frequency_hz);
    const Point2Px m = view_.to_px({(l.x1_mm + l.x2_mm) / 2, (l.y1_mm + l.y2_mm) / 2});
    dl->AddText(ImVec2(m.x + 4, m.y - view_.length_px(l.width_mm) / 2 - 16), with_alpha(col, 255), label);
  }
}

void CanvasView::draw_surface(ImDrawList* dl, const Surface& s, const RectMm& bounds, bool highlighted) {
  const float ppm = static_cast<float>(view_.px_per_mm());
  const ImU32 col = highlighted ? kHighlight : kSurfaceColour;
  // Fill and outline.
  if (s.shape == SurfaceShape::rect) {
    const ImVec2 a = iv(view_.to_px({s.x_mm, s.y_mm}));
    const ImVec2 b = iv(view_.to_px({s.x_mm + s.width_mm, s.y_mm + s.height_mm}));
    dl->AddRectFilled(a, b, with_alpha(col, 40));
    dl->AddRect(a, b, with_alpha(col, 255), 0, 0, 1.5f);
  } else if (s.shape == SurfaceShape::ellipse) {
    const int segments = std::clamp(static_cast<int>((s.rx_mm + s.ry_mm) * ppm / 3), 16, 128);
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i < segments; ++i) {
        const double t = 2 * std::numbers::pi * i / segments;
        dl->PathLineTo(iv(view_.to_px({s.cx_mm + s.rx_mm * std::cos(t), s.cy_mm + s.ry_mm * std::sin(t)})));
      }
      if (pass == 0) {
        dl->PathFillConvex(with_alpha(col, 40));
      } else {
        dl->PathStroke(with_alpha(col, 255), ImDrawFlags_Closed, 1.5f);
      }
    }
  } else if (s.points.size() >= 2) {
    // At screen resolution and in bounded runs: a huge polygon neither overflows ImGui's stack
    // nor costs more than the pixels it covers (editor/core/polyline_lod.hpp).
    outline_px_.clear();
    for (const Point2Mm& p : s.points) outline_px_.push_back(view_.to_px(p));
    decimate_polyline_px(outline_px_, 1.0f, true, outline_lod_px_);
    for_each_stroke_run(outline_lod_px_, [&](const Point2Px* first, std::size_t count) {
      for (std::size_t i = 0; i < count; ++i) dl->PathLineTo(iv(first[i]));
      dl->PathStroke(with_alpha(col, 255), ImDrawFlags_None, 1.5f);
    });
  }
  // Pattern stripes at the spatial period (every k-th period when they would be too dense).
  const double period = std::max(1e-3, s.period_mm);
  int every = 1;
  while (period * every * ppm < 4.0) every *= 2;
  const double stride = period * every;
  const float thickness = s.pattern == SurfacePattern::square ? std::max(1.0f, static_cast<float>(stride * ppm * 0.5))
                                                              : 1.0f;
  // The stripes at the pattern's crests, as opaque as the palette makes them there.
  const int alpha = opacity_alpha(palette::surface_opacity(s, std::ceil(bounds.x0_mm / stride) * stride + period / 4));
  const double start = std::ceil(bounds.x0_mm / stride) * stride;
  int count = 0;
  for (double gx = start; gx <= bounds.x1_mm && count < 2000; gx += stride, ++count) {
    surface_vertical_spans(s, gx, spans_);
    for (const auto& [y0, y1] : spans_) {
      const ImVec2 top = iv(view_.to_px({gx, y0}));
      const ImVec2 bottom = iv(view_.to_px({gx, y1}));
      if (s.pattern == SurfacePattern::triangle) {
        // A zigzag reads as a triangle wave.
        const float half = std::max(1.0f, static_cast<float>(stride * ppm * 0.25));
        const float seg = std::max(4.0f, 2 * half);
        float yy = top.y;
        bool right = true;
        while (yy < bottom.y) {
          const float ny = std::min(bottom.y, yy + seg);
          dl->AddLine(ImVec2(top.x + (right ? -half : half), yy), ImVec2(top.x + (right ? half : -half), ny),
                      with_alpha(col, alpha), 1.0f);
          right = !right;
          yy = ny;
        }
      } else {
        dl->AddLine(top, bottom, with_alpha(col, s.pattern == SurfacePattern::square ? alpha / 2 : alpha), thickness);
      }
    }
  }
  if (bounds.width_mm() * ppm > 60 && bounds.height_mm() * ppm > 24) {
    char label[48];
    static constexpr const char* kPatterns[] = {"sine", "square", "triangle"};
    std::snprintf(label, sizeof label, "%s, period %.3g mm", kPatterns[static_cast<int>(s.pattern)], s.period_mm);
    const Point2Px tl = view_.to_px({bounds.x0_mm, bounds.y0_mm});
    dl->AddText(ImVec2(tl.x + 4, tl.y + 2), with_alpha(col, 255), label);
  }
}

void CanvasView::draw_element(ImDrawList* dl, const Element& element, bool highlighted) {
  const float ppm = static_cast<float>(view_.px_per_mm());
  const auto bounds = element_bounds(element);
  // Level of detail: a primitive a few pixels across shows only its colour and place.
  if (!std::holds_alternative<Group>(element.body) && bounds &&
      std::max(bounds->width_mm(), bounds->height_mm()) * ppm < 6.0) {
    const ImU32 col = highlighted                                  ? kHighlight
                      : std::holds_alternative<Dot>(element.body)  ? kDotColour
                      : std::holds_alternative<Line>(element.body) ? line_colour(std::get<Line>(element.body))
                                                                   : kSurfaceColour;
    dl->AddRectFilled(iv(view_.to_px({bounds->x0_mm, bounds->y0_mm})), iv(view_.to_px({bounds->x1_mm, bounds->y1_mm})),
                      with_alpha(col, 200));
    return;
  }
  if (const auto* d = std::get_if<Dot>(&element.body)) {
    const Point2Px c = view_.to_px({d->x_mm, d->y_mm});
    const float r = std::max(2.0f, view_.length_px(d->radius_mm));
    const ImU32 col = highlighted ? kHighlight : kDotColour;
    dl->AddCircleFilled(iv(c), r, with_alpha(col, opacity_alpha(palette::stroke_opacity(d->gain))));
    dl->AddCircle(iv(c), r, with_alpha(col, 255), 0, 1.5f);
  } else if (const auto* l = std::get_if<Line>(&element.body)) {
    draw_line(dl, *l, highlighted);
  } else if (const auto* s = std::get_if<Surface>(&element.body)) {
    if (bounds) draw_surface(dl, *s, *bounds, highlighted);
  } else if (const auto* g = std::get_if<Group>(&element.body)) {
    draw_document(dl, g->children);
    if (bounds) {
      dl->AddRect(iv(view_.to_px({bounds->x0_mm, bounds->y0_mm})), iv(view_.to_px({bounds->x1_mm, bounds->y1_mm})),
                  IM_COL32(150, 150, 160, 160), 0, 0, 1.0f);
    }
  }
}

void CanvasView::draw_picture(ImDrawList* dl) {
  const std::vector<Element>& elements = doc_.image().children;
  const bool dragging = drag_ == Drag::moving || drag_ == Drag::resizing || drag_ == Drag::vertex;
  if (!cache_ || !cache_->usable()) {
    draw_page(dl);
    draw_document(dl, elements);
    playback_.draw_feel_marks(dl, view_);
    return;
  }
  CanvasCacheKey key;
  key.change = dragging ? drag_base_change_ : doc_.change_count();
  key.feel = playback_.feel().generation();
  key.px_per_mm = view_.px_per_mm();
  const Point2Px origin = view_.page_origin_px();
  key.origin_x_px = origin.x;
  key.origin_y_px = origin.y;
  key.width_px = static_cast<int>(canvas_w_);
  key.height_px = static_cast<int>(canvas_h_);
  key.grid = show_grid_;
  if (dragging) key.left_out = doc_.selection();  // drawn live below, on top of the rest
  if (playback_.on()) {
    for (std::size_t i = 0; i < elements.size(); ++i) {
      if (!std::holds_alternative<Group>(elements[i].body) && playback_.contacted(elements[i])) key.highlighted.push_back(i);
    }
  }
  if (ImDrawList* picture = cache_->begin(key, canvas_x_, canvas_y_)) {
    picture->AddRectFilled(ImVec2(canvas_x_, canvas_y_), ImVec2(canvas_x_ + canvas_w_, canvas_y_ + canvas_h_),
                           IM_COL32(60, 60, 66, 255));
    draw_page(picture);
    draw_document(picture, elements, key.left_out);
    playback_.draw_feel_marks(picture, view_);
    cache_->end();
  }
  cache_->show(dl);
  for (const std::string& id : key.left_out) {
    if (const Element* e = doc_.find(id)) draw_element(dl, *e, false);
  }
}

void CanvasView::draw_document(ImDrawList* dl, const std::vector<Element>& elements,
                               const std::vector<std::string>& left_out) {
  const Point2Mm view_min = view_.to_mm({canvas_x_, canvas_y_});
  const Point2Mm view_max = view_.to_mm({canvas_x_ + canvas_w_, canvas_y_ + canvas_h_});
  const RectMm visible{view_min.x_mm, view_min.y_mm, view_max.x_mm, view_max.y_mm};
  for (const Element& e : elements) {
    const auto b = element_bounds(e);
    if (!b || !b->intersects(visible)) continue;
    if (!left_out.empty() && std::find(left_out.begin(), left_out.end(), e.id) != left_out.end()) continue;
    const bool group = std::holds_alternative<Group>(e.body);
    draw_element(dl, e, !group && playback_.contacted(e));
  }
}

void CanvasView::draw_selection(ImDrawList* dl) const {
  for (const std::string& id : doc_.selection()) {
    const Element* e = doc_.find(id);
    if (!e) continue;
    if (auto b = element_bounds(*e)) {
      dl->AddRect(iv(view_.to_px({b->x0_mm, b->y0_mm})), iv(view_.to_px({b->x1_mm, b->y1_mm})),
                  kSelectionColour, 0, 0, 1.0f);
    }
  }
  if (auto b = doc_.selection_bounds(); b && tool_ == Tool::select && !playback_.on()) {
    for (int i = 0; i < 8; ++i) {
      const Point2Px h = view_.to_px(handle_position(*b, i));
      dl->AddRectFilled(ImVec2(h.x - kHandlePx, h.y - kHandlePx), ImVec2(h.x + kHandlePx, h.y + kHandlePx), kHandleFill);
      dl->AddRect(ImVec2(h.x - kHandlePx, h.y - kHandlePx), ImVec2(h.x + kHandlePx, h.y + kHandlePx),
                  kSelectionColour);
    }
  }
  draw_vertex_handles(dl);
}

}  // namespace vimg::editor
