// The canvas: the page at physical scale, rulers in mm, grid, every primitive drawn by kind, and
// the mouse in drawing mode (place, select, move, resize, box-select, pan, zoom).
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "editor/core/element_ids.hpp"
#include "editor/core/polyline_lod.hpp"
#include "editor/editor_app.hpp"
#include "player/touch_event.hpp"
#include "storage/image_io.hpp"

namespace vimg::editor {
namespace {

constexpr float kRulerPx = 22.0f;
constexpr float kHandlePx = 5.0f;
constexpr const char* kLibraryPayload = "VIMG_LIBRARY_FILE";

constexpr ImU32 kDotColour = IM_COL32(255, 150, 40, 255);
constexpr ImU32 kLineColour = IM_COL32(70, 150, 255, 255);
constexpr ImU32 kSurfaceColour = IM_COL32(70, 200, 130, 255);
constexpr ImU32 kHighlight = IM_COL32(255, 60, 60, 255);
constexpr ImU32 kSelection = IM_COL32(255, 255, 255, 255);

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

// The x-intervals of the vertical line x inside the surface (stripes run vertically).
void surface_vertical_spans(const Surface& s, double x, std::vector<std::pair<double, double>>& spans) {
  Surface t = s;  // transpose and reuse the horizontal case
  std::swap(t.x_mm, t.y_mm);
  std::swap(t.width_mm, t.height_mm);
  std::swap(t.cx_mm, t.cy_mm);
  std::swap(t.rx_mm, t.ry_mm);
  for (Point2Mm& p : t.points) std::swap(p.x_mm, p.y_mm);
  surface_spans(t, x, spans);
}

// The eight resize handles of a selection box, clockwise from the top-left corner; handle i
// moves the box's edges as Canvas's resize code expects.
std::array<ImVec2, 8> handle_positions_px(const Point2Px& top_left, const Point2Px& bottom_right) {
  const float xs[3] = {top_left.x, (top_left.x + bottom_right.x) / 2, bottom_right.x};
  const float ys[3] = {top_left.y, (top_left.y + bottom_right.y) / 2, bottom_right.y};
  static constexpr int kHx[8] = {0, 1, 2, 2, 2, 1, 0, 0};
  static constexpr int kHy[8] = {0, 0, 0, 1, 2, 2, 2, 1};
  std::array<ImVec2, 8> handles;
  for (int i = 0; i < 8; ++i) handles[static_cast<std::size_t>(i)] = ImVec2(xs[kHx[i]], ys[kHy[i]]);
  return handles;
}

}  // namespace

double EditorApp::snap_step_mm() const { return grid_step_mm(view_.px_per_mm(), 8.0); }

Point2Mm EditorApp::snapped(Point2Mm p) const {
  if (!snap_) return p;
  const double step = snap_step_mm();
  return Point2Mm{snap_mm(p.x_mm, step), snap_mm(p.y_mm, step)};
}

bool EditorApp::contacted(const Element& element) const {
  if (!play_mode_ || !play_) return false;
  for (const auto& f : play_->fingers()) {
    if (f && element_contains(element, Point2Mm{f->x_mm, f->y_mm}, 0.0)) return true;
  }
  return false;
}

void EditorApp::draw_rulers_and_grid(ImDrawList* dl, float x, float y, float w, float h) {
  const Image& image = doc_.image();
  const Point2Px p0 = view_.to_px({0, 0});
  const Point2Px p1 = view_.to_px({image.width_mm, image.height_mm});
  dl->AddRectFilled(iv(p0), iv(p1), IM_COL32(248, 247, 242, 255));
  const double ppm = view_.px_per_mm();
  const double minor = grid_step_mm(ppm, 8.0);
  const double major = grid_step_mm(ppm, 60.0);
  if (show_grid_) {
    const ImU32 minor_c = IM_COL32(225, 225, 220, 255);
    const ImU32 major_c = IM_COL32(195, 195, 190, 255);
    for (double gx = 0; gx <= image.width_mm + 1e-9; gx += minor) {
      const float px = view_.to_px({gx, 0}).x;
      if (px < x || px > x + w) continue;
      const bool is_major = std::abs(std::remainder(gx, major)) < 1e-6;
      dl->AddLine(ImVec2(px, p0.y), ImVec2(px, p1.y), is_major ? major_c : minor_c);
    }
    for (double gy = 0; gy <= image.height_mm + 1e-9; gy += minor) {
      const float py = view_.to_px({0, gy}).y;
      if (py < y || py > y + h) continue;
      const bool is_major = std::abs(std::remainder(gy, major)) < 1e-6;
      dl->AddLine(ImVec2(p0.x, py), ImVec2(p1.x, py), is_major ? major_c : minor_c);
    }
  }
  dl->AddRect(iv(p0), iv(p1), IM_COL32(120, 120, 120, 255));
}

void EditorApp::draw_element(ImDrawList* dl, const Element& element, bool highlighted) {
  const float ppm = static_cast<float>(view_.px_per_mm());
  // Level of detail: a primitive a few pixels across shows only its colour and place.
  if (!std::holds_alternative<Group>(element.body)) {
    if (const auto b = element_bounds(element); b && std::max(b->width_mm(), b->height_mm()) * ppm < 6.0) {
      const ImU32 col = highlighted                                  ? kHighlight
                        : std::holds_alternative<Dot>(element.body)  ? kDotColour
                        : std::holds_alternative<Line>(element.body) ? kLineColour
                                                                     : kSurfaceColour;
      dl->AddRectFilled(iv(view_.to_px({b->x0_mm, b->y0_mm})), iv(view_.to_px({b->x1_mm, b->y1_mm})),
                        with_alpha(col, 200));
      return;
    }
  }
  if (const auto* d = std::get_if<Dot>(&element.body)) {
    const Point2Px c = view_.to_px({d->x_mm, d->y_mm});
    const float r = std::max(2.0f, view_.length_px(d->radius_mm));
    const ImU32 col = highlighted ? kHighlight : kDotColour;
    dl->AddCircleFilled(iv(c), r, with_alpha(col, 80 + static_cast<int>(175 * std::clamp(d->gain, 0.0, 1.0))));
    dl->AddCircle(iv(c), r, with_alpha(col, 255), 0, 1.5f);
    return;
  }
  if (const auto* l = std::get_if<Line>(&element.body)) {
    const Point2Px a = view_.to_px({l->x1_mm, l->y1_mm});
    const Point2Px b = view_.to_px({l->x2_mm, l->y2_mm});
    const ImU32 col = highlighted ? kHighlight : kLineColour;
    dl->AddLine(iv(a), iv(b), with_alpha(col, 70), std::max(1.0f, view_.length_px(l->width_mm)));
    // A wave along the segment: one drawn cycle per 1000/f mm, so a higher pitch looks denser.
    const double len = std::hypot(l->x2_mm - l->x1_mm, l->y2_mm - l->y1_mm);
    if (len > 0 && len * ppm > 6) {
      const double ux = (l->x2_mm - l->x1_mm) / len, uy = (l->y2_mm - l->y1_mm) / len;
      const double wavelength_mm = std::max(0.5, 1000.0 / std::max(1.0, l->frequency_hz));
      const double amp = l->width_mm * 0.35;
      const int steps = std::clamp(static_cast<int>(len / wavelength_mm * 12), 8, 400);
      ImVec2 prev = iv(a);
      for (int i = 1; i <= steps; ++i) {
        const double t = len * i / steps;
        const double off = amp * std::sin(2 * std::numbers::pi * t / wavelength_mm);
        const ImVec2 cur = iv(view_.to_px({l->x1_mm + ux * t - uy * off, l->y1_mm + uy * t + ux * off}));
        dl->AddLine(prev, cur, with_alpha(col, 255), 1.5f);
        prev = cur;
      }
      if (len * ppm > 40) {
        char label[32];
        std::snprintf(label, sizeof label, "%.0f Hz", l->frequency_hz);
        const Point2Px m = view_.to_px({(l->x1_mm + l->x2_mm) / 2, (l->y1_mm + l->y2_mm) / 2});
        dl->AddText(ImVec2(m.x + 4, m.y - view_.length_px(l->width_mm) / 2 - 16), with_alpha(col, 255), label);
      }
    } else {
      dl->AddLine(iv(a), iv(b), with_alpha(col, 255), 1.5f);
    }
    return;
  }
  if (const auto* s = std::get_if<Surface>(&element.body)) {
    const ImU32 col = highlighted ? kHighlight : kSurfaceColour;
    const auto bounds = element_bounds(element);
    if (!bounds) return;
    // Fill and outline.
    if (s->shape == SurfaceShape::rect) {
      dl->AddRectFilled(iv(view_.to_px({s->x_mm, s->y_mm})), iv(view_.to_px({s->x_mm + s->width_mm, s->y_mm + s->height_mm})),
                        with_alpha(col, 40));
      dl->AddRect(iv(view_.to_px({s->x_mm, s->y_mm})), iv(view_.to_px({s->x_mm + s->width_mm, s->y_mm + s->height_mm})),
                  with_alpha(col, 255), 0, 0, 1.5f);
    } else if (s->shape == SurfaceShape::ellipse) {
      const int segments = std::clamp(static_cast<int>((s->rx_mm + s->ry_mm) * ppm / 3), 16, 128);
      for (int pass = 0; pass < 2; ++pass) {
        for (int i = 0; i < segments; ++i) {
          const double t = 2 * std::numbers::pi * i / segments;
          dl->PathLineTo(iv(view_.to_px({s->cx_mm + s->rx_mm * std::cos(t), s->cy_mm + s->ry_mm * std::sin(t)})));
        }
        if (pass == 0) {
          dl->PathFillConvex(with_alpha(col, 40));
        } else {
          dl->PathStroke(with_alpha(col, 255), ImDrawFlags_Closed, 1.5f);
        }
      }
    } else if (s->points.size() >= 2) {
      // At screen resolution and in bounded runs: a huge polygon neither overflows ImGui's stack
      // nor costs more than the pixels it covers (editor/core/polyline_lod.hpp).
      outline_px_.clear();
      for (const Point2Mm& p : s->points) outline_px_.push_back(view_.to_px(p));
      decimate_polyline_px(outline_px_, 1.0f, true, outline_lod_px_);
      for_each_stroke_run(outline_lod_px_, [&](const Point2Px* first, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) dl->PathLineTo(iv(first[i]));
        dl->PathStroke(with_alpha(col, 255), ImDrawFlags_None, 1.5f);
      });
    }
    // Pattern stripes at the spatial period (every k-th period when they would be too dense).
    const double period = std::max(1e-3, s->period_mm);
    int every = 1;
    while (period * every * ppm < 4.0) every *= 2;
    const double stride = period * every;
    const float thickness = s->pattern == SurfacePattern::square ? std::max(1.0f, static_cast<float>(stride * ppm * 0.5))
                                                                 : 1.0f;
    const int alpha = 60 + static_cast<int>(150 * std::clamp(s->gain, 0.0, 1.0));
    std::vector<std::pair<double, double>> spans;
    const double start = std::ceil(bounds->x0_mm / stride) * stride;
    int count = 0;
    for (double gx = start; gx <= bounds->x1_mm && count < 2000; gx += stride, ++count) {
      surface_vertical_spans(*s, gx, spans);
      for (const auto& [y0, y1] : spans) {
        const ImVec2 top = iv(view_.to_px({gx, y0}));
        const ImVec2 bottom = iv(view_.to_px({gx, y1}));
        if (s->pattern == SurfacePattern::triangle) {
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
          dl->AddLine(top, bottom, with_alpha(col, s->pattern == SurfacePattern::square ? alpha / 2 : alpha), thickness);
        }
      }
    }
    if ((bounds->width_mm()) * ppm > 60 && bounds->height_mm() * ppm > 24) {
      char label[48];
      static constexpr const char* kPatterns[] = {"sine", "square", "triangle"};
      std::snprintf(label, sizeof label, "%s, period %.3g mm", kPatterns[static_cast<int>(s->pattern)], s->period_mm);
      const Point2Px tl = view_.to_px({bounds->x0_mm, bounds->y0_mm});
      dl->AddText(ImVec2(tl.x + 4, tl.y + 2), with_alpha(col, 255), label);
    }
    return;
  }
  if (const auto* g = std::get_if<Group>(&element.body)) {
    draw_document(dl, g->children, true);
    if (auto b = element_bounds(element)) {
      dl->AddRect(iv(view_.to_px({b->x0_mm, b->y0_mm})), iv(view_.to_px({b->x1_mm, b->y1_mm})),
                  IM_COL32(150, 150, 160, 160), 0, 0, 1.0f);
    }
  }
}

void EditorApp::draw_document(ImDrawList* dl, const std::vector<Element>& elements, bool in_group) {
  const Point2Mm view_min = view_.to_mm({canvas_x_, canvas_y_});
  const Point2Mm view_max = view_.to_mm({canvas_x_ + canvas_w_, canvas_y_ + canvas_h_});
  const RectMm visible{view_min.x_mm, view_min.y_mm, view_max.x_mm, view_max.y_mm};
  for (const Element& e : elements) {
    const auto b = element_bounds(e);
    if (!b || !b->intersects(visible)) continue;
    const bool group = std::holds_alternative<Group>(e.body);
    draw_element(dl, e, !group && contacted(e));
  }
  (void)in_group;
}

void EditorApp::draw_selection(ImDrawList* dl) {
  for (const std::string& id : doc_.selection()) {
    const Element* e = doc_.find(id);
    if (!e) continue;
    if (auto b = element_bounds(*e)) {
      dl->AddRect(iv(view_.to_px({b->x0_mm, b->y0_mm})), iv(view_.to_px({b->x1_mm, b->y1_mm})),
                  IM_COL32(40, 120, 255, 255), 0, 0, 1.0f);
    }
  }
  if (auto b = doc_.selection_bounds(); b && tool_ == Tool::select && !play_mode_) {
    for (const ImVec2& h : handle_positions_px(view_.to_px({b->x0_mm, b->y0_mm}), view_.to_px({b->x1_mm, b->y1_mm}))) {
      dl->AddRectFilled(ImVec2(h.x - kHandlePx, h.y - kHandlePx), ImVec2(h.x + kHandlePx, h.y + kHandlePx), kSelection);
      dl->AddRect(ImVec2(h.x - kHandlePx, h.y - kHandlePx), ImVec2(h.x + kHandlePx, h.y + kHandlePx),
                  IM_COL32(40, 120, 255, 255));
    }
  }
}

void EditorApp::draw_play_overlay(ImDrawList* dl) {
  if (!play_) return;
  const double now = monotonic_s();
  play_->forget_trail_older_than(now - 1.5);
  const auto& trail = play_->trail();
  for (std::size_t i = 1; i < trail.size(); ++i) {
    const double age = now - trail[i].time_s;
    const int alpha = static_cast<int>(std::clamp(1.0 - age / 1.5, 0.0, 1.0) * 220);
    if (trail[i].time_s - trail[i - 1].time_s > 0.2) continue;  // a new stroke
    dl->AddLine(iv(view_.to_px({trail[i - 1].x_mm, trail[i - 1].y_mm})), iv(view_.to_px({trail[i].x_mm, trail[i].y_mm})),
                IM_COL32(200, 40, 200, alpha), 3.0f);
  }
  for (const auto& f : play_->fingers()) {
    if (f) dl->AddCircle(iv(view_.to_px({f->x_mm, f->y_mm})), 9.0f, IM_COL32(200, 40, 200, 255), 0, 2.0f);
  }
}

void EditorApp::draw_canvas(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##canvas", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PopStyleVar();
  canvas_x_ = x + kRulerPx;
  canvas_y_ = y + kRulerPx;
  canvas_w_ = w - kRulerPx;
  canvas_h_ = h - kRulerPx;
  view_.set_origin_px(canvas_x_ + 20.0f, canvas_y_ + 20.0f);
  print_layout("canvas", canvas_x_, canvas_y_, canvas_w_, canvas_h_);
  if (options_.print_layout) {
    const Point2Px o = view_.page_origin_px();
    char name[64];
    std::snprintf(name, sizeof name, "page_origin_ppm%.4f", view_.px_per_mm());
    print_layout(name, o.x, o.y, 0, 0);
  }

  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(60, 60, 66, 255));
  dl->PushClipRect(ImVec2(canvas_x_, canvas_y_), ImVec2(canvas_x_ + canvas_w_, canvas_y_ + canvas_h_), true);
  draw_rulers_and_grid(dl, canvas_x_, canvas_y_, canvas_w_, canvas_h_);
  draw_document(dl, doc_.image().children, false);
  draw_selection(dl);
  if (play_mode_) draw_play_overlay(dl);

  // The mouse.
  ImGui::SetCursorScreenPos(ImVec2(canvas_x_, canvas_y_));
  ImGui::InvisibleButton("##canvas_area", ImVec2(canvas_w_, canvas_h_),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  if (hovered && io.MouseWheel != 0.0f) {
    view_.zoom_at(std::pow(1.15, static_cast<double>(io.MouseWheel)), io.MousePos.x, io.MousePos.y);
  }
  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) drag_ = Drag::panning;
  if (drag_ == Drag::panning) {
    view_.pan_px(io.MouseDelta.x, io.MouseDelta.y);
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Middle)) drag_ = Drag::none;
  }
  if (!play_mode_) canvas_mouse_drawing_mode();

  // Previews of what is being drawn.
  const Point2Mm mouse_mm = snapped(view_.to_mm({io.MousePos.x, io.MousePos.y}));
  if (drag_ == Drag::placing) {
    const ImU32 c = IM_COL32(40, 120, 255, 255);
    const Point2Px a = view_.to_px(drag_start_mm_);
    const Point2Px b = view_.to_px(mouse_mm);
    if (tool_ == Tool::line) {
      dl->AddLine(iv(a), iv(b), c, 2.0f);
    } else if (tool_ == Tool::dot) {
      dl->AddCircle(iv(a), std::hypot(b.x - a.x, b.y - a.y), c, 0, 1.5f);
    } else if (tool_ == Tool::ellipse) {
      dl->AddRect(iv(a), iv(b), with_alpha(c, 90));
      const float cx = (a.x + b.x) / 2, cy = (a.y + b.y) / 2;
      const float rx = std::abs(b.x - a.x) / 2, ry = std::abs(b.y - a.y) / 2;
      for (int i = 0; i < 48; ++i) {
        const float t = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / 48.0f;
        dl->PathLineTo(ImVec2(cx + rx * std::cos(t), cy + ry * std::sin(t)));
      }
      dl->PathStroke(c, ImDrawFlags_Closed, 1.5f);
    } else {
      dl->AddRect(iv(a), iv(b), c, 0, 0, 1.5f);
    }
  }
  if (drag_ == Drag::box) {
    dl->AddRectFilled(iv(view_.to_px(drag_start_mm_)), io.MousePos, IM_COL32(40, 120, 255, 40));
    dl->AddRect(iv(view_.to_px(drag_start_mm_)), io.MousePos, IM_COL32(40, 120, 255, 200));
  }
  if (!polygon_points_.empty()) {
    for (std::size_t i = 0; i < polygon_points_.size(); ++i) {
      const ImVec2 p = iv(view_.to_px(polygon_points_[i]));
      dl->AddCircleFilled(p, 3.0f, IM_COL32(40, 120, 255, 255));
      const ImVec2 q = i + 1 < polygon_points_.size() ? iv(view_.to_px(polygon_points_[i + 1])) : iv(view_.to_px(mouse_mm));
      dl->AddLine(p, q, IM_COL32(40, 120, 255, 255), 1.5f);
    }
  }
  dl->PopClipRect();

  // Rulers in mm along the top and the left.
  const ImU32 ruler_bg = IM_COL32(40, 40, 44, 255);
  const ImU32 tick = IM_COL32(200, 200, 200, 255);
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + kRulerPx), ruler_bg);
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + kRulerPx, y + h), ruler_bg);
  const double minor = grid_step_mm(view_.px_per_mm(), 6.0);
  const double major = grid_step_mm(view_.px_per_mm(), 50.0);
  const Point2Mm from = view_.to_mm({canvas_x_, canvas_y_});
  const Point2Mm to = view_.to_mm({canvas_x_ + canvas_w_, canvas_y_ + canvas_h_});
  for (double mx = std::ceil(from.x_mm / minor) * minor; mx <= to.x_mm; mx += minor) {
    const float px = view_.to_px({mx, 0}).x;
    const bool is_major = std::abs(std::remainder(mx, major)) < 1e-6;
    dl->AddLine(ImVec2(px, y + kRulerPx - (is_major ? 10.0f : 4.0f)), ImVec2(px, y + kRulerPx), tick);
    if (is_major) {
      char label[16];
      std::snprintf(label, sizeof label, "%g", std::round(mx * 100) / 100);
      dl->AddText(ImVec2(px + 2, y + 1), tick, label);
    }
  }
  for (double my = std::ceil(from.y_mm / minor) * minor; my <= to.y_mm; my += minor) {
    const float py = view_.to_px({0, my}).y;
    const bool is_major = std::abs(std::remainder(my, major)) < 1e-6;
    dl->AddLine(ImVec2(x + kRulerPx - (is_major ? 10.0f : 4.0f), py), ImVec2(x + kRulerPx, py), tick);
    if (is_major) {
      char label[16];
      std::snprintf(label, sizeof label, "%g", std::round(my * 100) / 100);
      dl->AddText(ImVec2(x + 1, py + 1), tick, label);
    }
  }
  dl->AddText(ImVec2(x + 3, y + 3), tick, "mm");
  if (hovered) {
    const Point2Mm m = view_.to_mm({io.MousePos.x, io.MousePos.y});
    char pos[48];
    std::snprintf(pos, sizeof pos, "%.1f, %.1f mm", m.x_mm, m.y_mm);
    dl->AddText(ImVec2(x + w - 110, y + h - 18), IM_COL32(230, 230, 230, 255), pos);
  }

  // Images dragged from the library land here.
  if (ImGui::BeginDragDropTarget()) {
    if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload(kLibraryPayload)) {
      const std::string path(static_cast<const char*>(payload->Data), static_cast<std::size_t>(payload->DataSize));
      drop_library_file(path, view_.to_mm({io.MousePos.x, io.MousePos.y}));
    }
    ImGui::EndDragDropTarget();
  }
  ImGui::End();
}

void EditorApp::canvas_mouse_drawing_mode() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const Point2Mm raw = view_.to_mm({io.MousePos.x, io.MousePos.y});
  const Point2Mm mouse = snapped(raw);
  const double tolerance_mm = 4.0 / view_.px_per_mm();

  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) ImGui::OpenPopup("canvas_menu");
  if (ImGui::BeginPopup("canvas_menu")) {
    const bool any = !doc_.selection().empty();
    if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, any)) doc_.duplicate_selection(5.0);
    if (ImGui::MenuItem("Delete", "Del", false, any)) doc_.delete_selection();
    if (ImGui::MenuItem("Copy", "Ctrl+C", false, any)) doc_.copy_selection();
    if (ImGui::MenuItem("Paste", "Ctrl+V", false, doc_.can_paste())) doc_.paste(5.0);
    ImGui::Separator();
    if (ImGui::MenuItem("Group", "Ctrl+G", false, any)) doc_.group_selection();
    if (ImGui::MenuItem("Ungroup", "Ctrl+Shift+G", false, any)) doc_.ungroup_selection();
    ImGui::Separator();
    if (ImGui::MenuItem("Bring Forward", "PgUp", false, any)) doc_.raise_selection();
    if (ImGui::MenuItem("Send Backward", "PgDn", false, any)) doc_.lower_selection();
    if (ImGui::MenuItem("Bring to Front", "Home", false, any)) doc_.bring_selection_to_front();
    if (ImGui::MenuItem("Send to Back", "End", false, any)) doc_.send_selection_to_back();
    ImGui::EndPopup();
  }

  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && drag_ == Drag::none) {
    if (tool_ == Tool::select) {
      // A handle of the selection?
      resize_handle_ = -1;
      if (auto b = doc_.selection_bounds()) {
        const auto handles = handle_positions_px(view_.to_px({b->x0_mm, b->y0_mm}), view_.to_px({b->x1_mm, b->y1_mm}));
        for (int i = 0; i < 8; ++i) {
          const ImVec2& h = handles[static_cast<std::size_t>(i)];
          if (std::abs(io.MousePos.x - h.x) <= kHandlePx + 1 && std::abs(io.MousePos.y - h.y) <= kHandlePx + 1) {
            resize_handle_ = i;
            resize_from_ = *b;
          }
        }
      }
      if (resize_handle_ >= 0) {
        doc_.begin_gesture();
        drag_ = Drag::resizing;
      } else if (auto id = doc_.element_at(raw, tolerance_mm)) {
        if (io.KeyShift) {
          doc_.toggle_selected(*id);
        } else {
          if (!doc_.is_selected(*id)) doc_.select_only(*id);
          doc_.begin_gesture();
          drag_ = Drag::moving;
          drag_start_mm_ = raw;
          drag_applied_mm_ = {0, 0};
        }
      } else {
        if (!io.KeyShift) doc_.clear_selection();
        drag_ = Drag::box;
        drag_start_mm_ = raw;
      }
    } else if (tool_ == Tool::polygon) {
      if (polygon_points_.size() >= 3) {
        const Point2Px first = view_.to_px(polygon_points_.front());
        if (std::hypot(first.x - io.MousePos.x, first.y - io.MousePos.y) < 8.0f || ImGui::IsMouseDoubleClicked(0)) {
          finish_polygon();
          return;
        }
      }
      polygon_points_.push_back(mouse);
    } else {
      drag_ = Drag::placing;
      drag_start_mm_ = mouse;
    }
  }

  if (drag_ == Drag::moving) {
    double dx = raw.x_mm - drag_start_mm_.x_mm;
    double dy = raw.y_mm - drag_start_mm_.y_mm;
    if (snap_) {
      dx = snap_mm(dx, snap_step_mm());
      dy = snap_mm(dy, snap_step_mm());
    }
    doc_.move_selection(dx - drag_applied_mm_.x_mm, dy - drag_applied_mm_.y_mm);
    drag_applied_mm_ = {dx, dy};
  } else if (drag_ == Drag::resizing) {
    RectMm r = resize_from_;
    static constexpr int kHx[8] = {0, 1, 2, 2, 2, 1, 0, 0};
    static constexpr int kHy[8] = {0, 0, 0, 1, 2, 2, 2, 1};
    const int hx = kHx[resize_handle_];
    const int hy = kHy[resize_handle_];
    if (hx == 0) r.x0_mm = std::min(mouse.x_mm, r.x1_mm - 0.1);
    if (hx == 2) r.x1_mm = std::max(mouse.x_mm, r.x0_mm + 0.1);
    if (hy == 0) r.y0_mm = std::min(mouse.y_mm, r.y1_mm - 0.1);
    if (hy == 2) r.y1_mm = std::max(mouse.y_mm, r.y0_mm + 0.1);
    if (auto current = doc_.selection_bounds()) doc_.resize_selection(*current, r);
  }

  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    switch (drag_) {
      case Drag::placing: finish_placing(drag_start_mm_, mouse); break;
      case Drag::moving:
      case Drag::resizing: doc_.end_gesture(); break;
      case Drag::box: doc_.select_in_rect(rect_from_corners(drag_start_mm_, raw), io.KeyShift); break;
      default: break;
    }
    if (drag_ != Drag::panning) drag_ = Drag::none;
  }
}

void EditorApp::finish_placing(Point2Mm a, Point2Mm b) {
  const double dragged_mm = std::hypot(b.x_mm - a.x_mm, b.y_mm - a.y_mm);
  const bool click = dragged_mm * view_.px_per_mm() < 3.0;
  Element e;
  switch (tool_) {
    case Tool::dot: e.body = Dot{a.x_mm, a.y_mm, click ? 2.0 : dragged_mm, 1.0}; break;
    case Tool::line: {
      Line l;
      l.x1_mm = a.x_mm;
      l.y1_mm = a.y_mm;
      l.x2_mm = click ? a.x_mm + 20.0 : b.x_mm;
      l.y2_mm = click ? a.y_mm : b.y_mm;
      e.body = l;
      break;
    }
    case Tool::rect: {
      Surface s;
      s.shape = SurfaceShape::rect;
      const RectMm r = click ? RectMm{a.x_mm, a.y_mm, a.x_mm + 20, a.y_mm + 20} : rect_from_corners(a, b);
      s.x_mm = r.x0_mm;
      s.y_mm = r.y0_mm;
      s.width_mm = std::max(0.1, r.width_mm());
      s.height_mm = std::max(0.1, r.height_mm());
      e.body = s;
      break;
    }
    case Tool::ellipse: {
      Surface s;
      s.shape = SurfaceShape::ellipse;
      const RectMm r = click ? RectMm{a.x_mm - 10, a.y_mm - 10, a.x_mm + 10, a.y_mm + 10} : rect_from_corners(a, b);
      s.cx_mm = (r.x0_mm + r.x1_mm) / 2;
      s.cy_mm = (r.y0_mm + r.y1_mm) / 2;
      s.rx_mm = std::max(0.05, r.width_mm() / 2);
      s.ry_mm = std::max(0.05, r.height_mm() / 2);
      e.body = s;
      break;
    }
    default: return;
  }
  doc_.add_element(std::move(e));
}

void EditorApp::finish_polygon() {
  if (polygon_points_.size() < 3) return;
  Surface s;
  s.shape = SurfaceShape::polygon;
  s.points = polygon_points_;
  Element e;
  e.body = std::move(s);
  polygon_points_.clear();
  doc_.add_element(std::move(e));
}

void EditorApp::drop_library_file(const std::string& path, Point2Mm at) {
  LoadResult result = load_image_file(path);
  if (!result.ok()) {
    report_error(result.diagnostics.empty() ? path + ": cannot open" : result.diagnostics.front().to_string());
    return;
  }
  Group group;
  group.name = std::filesystem::path(path).stem().string();
  group.children = std::move(result.image->children);
  Element e;
  e.body = std::move(group);
  // The dropped image's top-left corner lands under the mouse.
  if (snap_) at = snapped(at);
  translate_element(e, at.x_mm, at.y_mm);
  doc_.add_element(std::move(e));
  status_ = "placed " + path;
}

}  // namespace vimg::editor
