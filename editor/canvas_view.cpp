// The canvas window: its region, rulers in mm, the previews of what is being drawn, the tool
// choice and the view commands. The picture is canvas_paint.cpp, the mouse canvas_mouse.cpp.
#include "editor/canvas_view.hpp"

#include <SDL.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "editor/canvas_cache.hpp"
#include "editor/core/layout_log.hpp"
#include "editor/playback.hpp"

namespace vimg::editor {
namespace {
ImVec2 iv(Point2Px p) { return ImVec2(p.x, p.y); }
constexpr ImU32 kDrawing = IM_COL32(40, 120, 255, 255);
}  // namespace

CanvasView::CanvasView(DocumentEditor& doc, const Playback& playback, Notices& notices, LayoutLog& layout)
    : doc_(doc), playback_(playback), notices_(notices), layout_(layout) {}

CanvasView::~CanvasView() = default;

void CanvasView::set_renderer(SDL_Renderer* renderer) {
  cache_ = renderer ? std::make_unique<CanvasCache>(renderer) : nullptr;
}

std::uint64_t CanvasView::cache_builds() const { return cache_ ? cache_->builds() : 0; }

void CanvasView::picture_lost() {
  if (cache_) cache_->invalidate();
}

void CanvasView::set_density(double px_per_mm, double zoom) {
  view_ = Viewport(px_per_mm);
  view_.set_zoom(zoom);
}

bool CanvasView::inside_px(float x, float y) const {
  return x >= canvas_x_ && y >= canvas_y_ && x < canvas_x_ + canvas_w_ && y < canvas_y_ + canvas_h_;
}

void CanvasView::actual_size() {
  view_.set_zoom(1.0);
  view_.reset_pan();
}

void CanvasView::zoom_by(double factor) { view_.zoom_at(factor, canvas_x_ + canvas_w_ / 2, canvas_y_ + canvas_h_ / 2); }

void CanvasView::cancel_interaction() {
  if (drag_ != Drag::none) {
    doc_.end_gesture();
    drag_ = Drag::none;
  }
  polygon_points_.clear();
}

bool CanvasView::handle_key(int sdl_keycode) {
  switch (sdl_keycode) {
    case SDLK_v: tool_ = Tool::select; return true;
    case SDLK_d: tool_ = Tool::dot; return true;
    case SDLK_l: tool_ = Tool::line; return true;
    case SDLK_r: tool_ = Tool::rect; return true;
    case SDLK_e: tool_ = Tool::ellipse; return true;
    case SDLK_p: tool_ = Tool::polygon; polygon_points_.clear(); return true;
    case SDLK_g: show_grid_ = !show_grid_; return true;
    case SDLK_s: snap_ = !snap_; return true;
    case SDLK_RETURN:
    case SDLK_KP_ENTER: finish_polygon(); return true;
    case SDLK_ESCAPE:
      if (!polygon_points_.empty()) {
        polygon_points_.clear();
      } else if (vertex_index_) {
        vertex_index_.reset();
      } else if (drag_ == Drag::none) {
        doc_.clear_selection();
      }
      return true;
    default: return false;
  }
}

void CanvasView::draw_tool_choice(bool playing) {
  ImGui::BeginDisabled(playing);
  struct ToolButton {
    Tool tool;
    const char* label;
  };
  static constexpr ToolButton kTools[] = {{Tool::select, "Select (V)"},       {Tool::dot, "DOT (D)"},
                                          {Tool::line, "LINE (L)"},           {Tool::rect, "SURFACE rect (R)"},
                                          {Tool::ellipse, "SURFACE ellipse (E)"}, {Tool::polygon, "SURFACE polygon (P)"}};
  for (const ToolButton& t : kTools) {
    if (ImGui::RadioButton(t.label, tool_ == t.tool)) {
      tool_ = t.tool;
      polygon_points_.clear();
    }
  }
  if (tool_ == Tool::polygon) ImGui::TextWrapped("Click the vertices; Enter or a click on the first one closes.");
  ImGui::Checkbox("Grid (G)", &show_grid_);
  ImGui::SameLine();
  ImGui::Checkbox("Snap (S)", &snap_);
  ImGui::EndDisabled();
}

void CanvasView::draw_previews(ImDrawList* dl) const {
  const ImGuiIO& io = ImGui::GetIO();
  const Point2Mm mouse_mm = snapped(view_.to_mm({io.MousePos.x, io.MousePos.y}));
  if (drag_ == Drag::placing) {
    const Point2Px a = view_.to_px(drag_start_mm_);
    const Point2Px b = view_.to_px(mouse_mm);
    if (tool_ == Tool::line) {
      dl->AddLine(iv(a), iv(b), kDrawing, 2.0f);
    } else if (tool_ == Tool::dot) {
      dl->AddCircle(iv(a), std::hypot(b.x - a.x, b.y - a.y), kDrawing, 0, 1.5f);
    } else if (tool_ == Tool::ellipse) {
      dl->AddRect(iv(a), iv(b), IM_COL32(40, 120, 255, 90));
      const float cx = (a.x + b.x) / 2, cy = (a.y + b.y) / 2;
      const float rx = std::abs(b.x - a.x) / 2, ry = std::abs(b.y - a.y) / 2;
      for (int i = 0; i < 48; ++i) {
        const float t = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / 48.0f;
        dl->PathLineTo(ImVec2(cx + rx * std::cos(t), cy + ry * std::sin(t)));
      }
      dl->PathStroke(kDrawing, ImDrawFlags_Closed, 1.5f);
    } else {
      dl->AddRect(iv(a), iv(b), kDrawing, 0, 0, 1.5f);
    }
  }
  if (drag_ == Drag::box) {
    dl->AddRectFilled(iv(view_.to_px(drag_start_mm_)), io.MousePos, IM_COL32(40, 120, 255, 40));
    dl->AddRect(iv(view_.to_px(drag_start_mm_)), io.MousePos, IM_COL32(40, 120, 255, 200));
  }
  for (std::size_t i = 0; i < polygon_points_.size(); ++i) {
    const ImVec2 p = iv(view_.to_px(polygon_points_[i]));
    dl->AddCircleFilled(p, 3.0f, kDrawing);
    const ImVec2 q = i + 1 < polygon_points_.size() ? iv(view_.to_px(polygon_points_[i + 1])) : iv(view_.to_px(mouse_mm));
    dl->AddLine(p, q, kDrawing, 1.5f);
  }
}

void CanvasView::draw_rulers(ImDrawList* dl, float x, float y, float w, float h) const {
  const ImU32 ruler_bg = IM_COL32(40, 40, 44, 255);
  const ImU32 tick = IM_COL32(200, 200, 200, 255);
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + kRulerPx), ruler_bg);
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + kRulerPx, y + h), ruler_bg);
  const double minor = grid_step_mm(view_.px_per_mm(), 6.0);
  const double major = grid_step_mm(view_.px_per_mm(), 50.0);
  const Point2Mm from = view_.to_mm({canvas_x_, canvas_y_});
  const Point2Mm to = view_.to_mm({canvas_x_ + canvas_w_, canvas_y_ + canvas_h_});
  char label[16];
  for (double mx = std::ceil(from.x_mm / minor) * minor; mx <= to.x_mm; mx += minor) {
    const float px = view_.to_px({mx, 0}).x;
    const bool is_major = std::abs(std::remainder(mx, major)) < 1e-6;
    dl->AddLine(ImVec2(px, y + kRulerPx - (is_major ? 10.0f : 4.0f)), ImVec2(px, y + kRulerPx), tick);
    if (is_major) {
      std::snprintf(label, sizeof label, "%g", std::round(mx * 100) / 100);
      dl->AddText(ImVec2(px + 2, y + 1), tick, label);
    }
  }
  for (double my = std::ceil(from.y_mm / minor) * minor; my <= to.y_mm; my += minor) {
    const float py = view_.to_px({0, my}).y;
    const bool is_major = std::abs(std::remainder(my, major)) < 1e-6;
    dl->AddLine(ImVec2(x + kRulerPx - (is_major ? 10.0f : 4.0f), py), ImVec2(x + kRulerPx, py), tick);
    if (is_major) {
      std::snprintf(label, sizeof label, "%g", std::round(my * 100) / 100);
      dl->AddText(ImVec2(x + 1, py + 1), tick, label);
    }
  }
  dl->AddText(ImVec2(x + 3, y + 3), tick, "mm");
}

void CanvasView::draw(float x, float y, float w, float h) {
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
  layout_.print("canvas", canvas_x_, canvas_y_, canvas_w_, canvas_h_);
  if (layout_.enabled()) {
    const Point2Px o = view_.page_origin_px();
    char name[64];
    std::snprintf(name, sizeof name, "page_origin_ppm%.4f", view_.px_per_mm());
    layout_.print(name, o.x, o.y, 0, 0);
  }

  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(60, 60, 66, 255));
  dl->PushClipRect(ImVec2(canvas_x_, canvas_y_), ImVec2(canvas_x_ + canvas_w_, canvas_y_ + canvas_h_), true);
  draw_picture(dl);
  draw_selection(dl);
  playback_.draw_overlay(dl, view_);

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
  if (!playback_.on()) handle_mouse();
  draw_previews(dl);
  dl->PopClipRect();

  draw_rulers(dl, x, y, w, h);
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

}  // namespace vimg::editor
