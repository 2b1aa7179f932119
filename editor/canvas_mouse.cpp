// The mouse on the canvas in drawing mode: place with the drawing tools, select (click, Shift,
// box), move, resize by the handles, the context menu, and library images dropped on the page.
#include <imgui.h>

#include <cmath>

#include "editor/canvas_view.hpp"
#include "storage/image_io.hpp"

namespace vimg::editor {

double CanvasView::snap_step_mm() const { return grid_step_mm(view_.px_per_mm(), 8.0); }

Point2Mm CanvasView::snapped(Point2Mm p) const {
  if (!snap_) return p;
  const double step = snap_step_mm();
  return Point2Mm{snap_mm(p.x_mm, step), snap_mm(p.y_mm, step)};
}

void CanvasView::context_menu() {
  if (!ImGui::BeginPopup("canvas_menu")) return;
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

// A left press on the canvas with nothing being dragged.
void CanvasView::press(Point2Mm raw, Point2Mm mouse) {
  const ImGuiIO& io = ImGui::GetIO();
  drag_base_change_ = doc_.change_count();
  const double tolerance_mm = 4.0 / view_.px_per_mm();
  if (tool_ == Tool::polygon) {
    if (polygon_points_.size() >= 3) {
      const Point2Px first = view_.to_px(polygon_points_.front());
      if (std::hypot(first.x - io.MousePos.x, first.y - io.MousePos.y) < 8.0f || ImGui::IsMouseDoubleClicked(0)) {
        finish_polygon();
        return;
      }
    }
    polygon_points_.push_back(mouse);
    return;
  }
  if (tool_ != Tool::select) {
    drag_ = Drag::placing;
    drag_start_mm_ = mouse;
    return;
  }
  // A vertex of the selected polygon or line, or a double-click on its edge?
  if (press_vertex(raw)) return;
  vertex_index_.reset();
  // A handle of the selection?
  resize_handle_ = -1;
  if (auto b = doc_.selection_bounds()) {
    for (int i = 0; i < 8; ++i) {
      const Point2Px h = view_.to_px(handle_position(*b, i));
      if (std::abs(io.MousePos.x - h.x) <= kHandlePx + 1 && std::abs(io.MousePos.y - h.y) <= kHandlePx + 1) {
        resize_handle_ = i;
        resize_from_ = *b;
      }
    }
  }
  if (resize_handle_ >= 0) {
    doc_.begin_gesture();
    drag_ = Drag::resizing;
    drag_start_mm_ = raw;
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
}

void CanvasView::handle_mouse() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool hovered = ImGui::IsItemHovered();
  const Point2Mm raw = view_.to_mm({io.MousePos.x, io.MousePos.y});
  const Point2Mm mouse = snapped(raw);

  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) ImGui::OpenPopup("canvas_menu");
  context_menu();

  if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && drag_ == Drag::none) {
    press(raw, mouse);
    if (tool_ == Tool::polygon && polygon_points_.empty()) return;  // the polygon was just closed
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
    // Snapped as a move is: the handle's edges move by whole snap steps.
    const RectMm r = resized_box(resize_from_, resize_handle_, raw.x_mm - drag_start_mm_.x_mm,
                                 raw.y_mm - drag_start_mm_.y_mm, snap_ ? snap_step_mm() : 0.0);
    if (auto current = doc_.selection_bounds()) doc_.resize_selection(*current, r);
  } else if (drag_ == Drag::vertex) {
    drag_vertex(mouse);
  }

  if (ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    switch (drag_) {
      case Drag::placing:
        if (auto e = place_element(tool_, drag_start_mm_, mouse, view_.px_per_mm())) doc_.add_element(std::move(*e));
        break;
      case Drag::moving:
      case Drag::resizing:
      case Drag::vertex: doc_.end_gesture(); break;
      case Drag::box: doc_.select_in_rect(rect_from_corners(drag_start_mm_, raw), io.KeyShift); break;
      default: break;
    }
    if (drag_ != Drag::panning) drag_ = Drag::none;
  }
}

void CanvasView::finish_polygon() {
  if (auto e = polygon_element(polygon_points_)) {
    polygon_points_.clear();
    doc_.add_element(std::move(*e));
  }
}

void CanvasView::drop_library_file(const std::string& path, Point2Mm at) {
  LoadResult result = load_image_file(path);
  if (!result.ok()) {
    notices_.report_error(result.diagnostics.empty() ? path + ": cannot open" : result.diagnostics.front().to_string());
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
  notices_.status = "placed " + path;
}

}  // namespace vimg::editor
