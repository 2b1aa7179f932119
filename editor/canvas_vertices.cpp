// Vertex handles on the canvas: drag a polygon's vertex or a line's end, double-click a polygon's
// edge to insert a vertex, Delete removes the chosen vertex (core/vertex_edit.hpp). Every edit
// goes through DocumentEditor::replace_element; a drag is one gesture, so one undo step.
#include <imgui.h>

#include "editor/canvas_view.hpp"
#include "editor/core/vertex_edit.hpp"
#include "editor/playback.hpp"
#include "storage/palette.hpp"

namespace vimg::editor {
namespace {
constexpr float kVertexPx = 7.0f;  // grab distance of a vertex handle
constexpr float kEdgePx = 5.0f;    // grab distance of an edge for inserting
constexpr ImU32 kSelection = IM_COL32(palette::kSelection.r, palette::kSelection.g, palette::kSelection.b, 255);
}  // namespace

const Element* CanvasView::vertex_target() const {
  if (tool_ != Tool::select || playback_.on() || doc_.selection().size() != 1) return nullptr;
  const Element* e = doc_.find(doc_.selection().front());
  return e && !vertex_points(*e).empty() ? e : nullptr;
}

bool CanvasView::press_vertex(Point2Mm raw) {
  const Element* target = vertex_target();
  if (!target) return false;
  const double ppm = view_.px_per_mm();
  const std::string id = target->id;
  const auto vertex = vertex_at(*target, raw, kVertexPx / ppm);
  if (!vertex && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    if (const auto edge = edge_at(*target, raw, kEdgePx / ppm)) {
      Element e = *target;
      if (insert_vertex(e, *edge)) {
        doc_.replace_element(id, e);
        vertex_owner_ = id;
        vertex_index_ = edge->index;
        notices_.status = "vertex inserted";
        return true;
      }
    }
  }
  if (!vertex) return false;
  vertex_owner_ = id;
  vertex_index_ = *vertex;
  doc_.begin_gesture();
  drag_ = Drag::vertex;
  return true;
}

void CanvasView::drag_vertex(Point2Mm mouse) {
  const Element* target = vertex_target();
  if (!target || !vertex_index_ || target->id != vertex_owner_) return;
  Element e = *target;
  if (move_vertex(e, *vertex_index_, mouse) && !(e == *target)) doc_.replace_element(vertex_owner_, e);
}

bool CanvasView::delete_chosen_vertex() {
  const Element* target = vertex_target();
  if (!target || !vertex_index_ || target->id != vertex_owner_) return false;
  Element e = *target;
  if (!delete_vertex(e, *vertex_index_)) {
    notices_.status = std::holds_alternative<Line>(e.body) ? "a line keeps both ends" : "a polygon keeps at least 3 vertices";
    return true;
  }
  doc_.replace_element(vertex_owner_, e);
  vertex_index_.reset();
  notices_.status = "vertex deleted";
  return true;
}

void CanvasView::draw_vertex_handles(ImDrawList* dl) const {
  const Element* target = vertex_target();
  if (!target) return;
  const bool chosen_here = target->id == vertex_owner_;
  const std::vector<Point2Mm> points = vertex_points(*target);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point2Px p = view_.to_px(points[i]);
    const bool chosen = chosen_here && vertex_index_ == i;
    dl->AddCircleFilled(ImVec2(p.x, p.y), 4.5f, chosen ? kSelection : IM_COL32(255, 255, 255, 255));
    dl->AddCircle(ImVec2(p.x, p.y), 4.5f, kSelection, 0, 1.5f);
  }
}

}  // namespace vimg::editor
