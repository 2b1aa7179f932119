// The inspector's properties panel (properties_panel.hpp).
#include "editor/properties_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <regex>

#include "editor/core/element_ids.hpp"
#include "editor/core/layout_log.hpp"

namespace vimg::editor {
namespace {

constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus;

struct FieldResult {
  bool changed = false;
  bool activated = false;
  bool deactivated = false;
  ImVec2 min;
  ImVec2 size;
};

// A number field with its unit and valid range; the value is clamped into the range. `open_min`
// and `open_max` mark exclusive bounds (the value stays just inside).
FieldResult number_field(const char* label, double& value, const char* unit, double min, double max,
                         bool open_min = false, bool open_max = false) {
  FieldResult r;
  double v = value;
  char range[96];
  std::snprintf(range, sizeof range, "%s%g, %g%s", open_min ? "(" : "[", min, max, open_max ? ")" : "]");
  ImGui::SetNextItemWidth(120);
  const bool edited = ImGui::InputDouble(label, &v, 0.0, 0.0, "%.6g");
  r.activated = ImGui::IsItemActivated();
  r.deactivated = ImGui::IsItemDeactivated();
  r.min = ImGui::GetItemRectMin();
  r.size = ImGui::GetItemRectSize();
  const bool hovered = ImGui::IsItemHovered();
  ImGui::SameLine();
  ImGui::TextDisabled("%s %s", unit, range);
  if (hovered) ImGui::SetTooltip("valid range %s %s", range, unit);
  if (!edited || !std::isfinite(v)) return r;
  const double eps = 1e-9 * std::max(1.0, std::abs(max - min));
  v = std::clamp(v, open_min ? min + eps : min, open_max ? max - eps : max);
  if (v == value) return r;
  value = v;
  r.changed = true;
  return r;
}

}  // namespace

PropertiesPanel::PropertiesPanel(DocumentEditor& doc, Notices& notices, LayoutLog& layout)
    : doc_(doc), notices_(notices), layout_(layout) {}

void PropertiesPanel::track_widget_gesture() {
  if (ImGui::IsItemActivated()) doc_.begin_gesture();
  if (ImGui::IsItemDeactivated()) doc_.end_gesture();
}

void PropertiesPanel::draw(float x, float y, float w, float h) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Properties", nullptr, kPanelFlags);
  if (doc_.selection().size() == 1) {
    draw_element(doc_.selection().front());
  } else if (doc_.selection().size() > 1) {
    ImGui::Text("%zu elements selected", doc_.selection().size());
    if (ImGui::Button("Group (Ctrl+G)")) doc_.group_selection();
  } else {
    draw_document();
  }
  ImGui::End();
}

void PropertiesPanel::draw_element(const std::string& id) {
  const Element* current = doc_.find(id);
  if (!current) return;
  Element e = *current;
  bool changed = false;
  auto field = [&](const char* label, double& v, const char* unit, double min, double max, bool open_min = false,
                   bool open_max = false) {
    const FieldResult r = number_field(label, v, unit, min, max, open_min, open_max);
    changed |= r.changed;
    if (r.activated) doc_.begin_gesture();
    if (r.deactivated) doc_.end_gesture();
    layout_.print(label, r.min.x, r.min.y, r.size.x, r.size.y);
  };
  // Wherever a coordinate may go: the document's size bound of the spec, with room off the canvas.
  constexpr double kCoord = 10000.0;

  ImGui::Text("%s", kind_name(e).c_str());
  if (id_for_ != id || !ImGui::IsAnyItemActive()) {
    std::snprintf(id_buffer_, sizeof id_buffer_, "%s", id.c_str());
    id_for_ = id;
  }
  ImGui::SetNextItemWidth(160);
  if (ImGui::InputText("id", id_buffer_, sizeof id_buffer_, ImGuiInputTextFlags_EnterReturnsTrue)) {
    static const std::regex kIdPattern("[A-Za-z_][A-Za-z0-9_.-]*");
    const std::string wanted = id_buffer_;
    const auto ids = collect_ids(doc_.image());
    if (!std::regex_match(wanted, kIdPattern)) {
      notices_.status = "an id starts with a letter or _ and holds letters, digits, _ . -";
    } else if (wanted != id && ids.count(wanted)) {
      notices_.status = "id " + wanted + " is already used";
    } else {
      e.id = wanted;
      changed = true;
    }
  }
  if (auto* d = std::get_if<Dot>(&e.body)) {
    field("x##dot", d->x_mm, "mm", -kCoord, kCoord);
    field("y##dot", d->y_mm, "mm", -kCoord, kCoord);
    field("radius", d->radius_mm, "mm", 0, kCoord, true);
    field("gain##dot", d->gain, "", 0, 1);
  } else if (auto* l = std::get_if<Line>(&e.body)) {
    field("x1", l->x1_mm, "mm", -kCoord, kCoord);
    field("y1", l->y1_mm, "mm", -kCoord, kCoord);
    field("x2", l->x2_mm, "mm", -kCoord, kCoord);
    field("y2", l->y2_mm, "mm", -kCoord, kCoord);
    field("width##line", l->width_mm, "mm", 0, kCoord, true);
    field("frequency", l->frequency_hz, "Hz", 0, 1000, true);
    field("damping", l->damping, "", 0, 1, true, true);
    field("gain##line", l->gain, "", 0, 1);
  } else if (auto* s = std::get_if<Surface>(&e.body)) {
    static constexpr const char* kShapes[] = {"rect", "ellipse", "polygon"};
    int shape = static_cast<int>(s->shape);
    ImGui::SetNextItemWidth(120);
    if (ImGui::Combo("shape", &shape, kShapes, 3)) {
      // Keep the same place and size in the new shape.
      const RectMm b = element_bounds(e).value_or(RectMm{0, 0, 10, 10});
      s->shape = static_cast<SurfaceShape>(shape);
      s->x_mm = b.x0_mm;
      s->y_mm = b.y0_mm;
      s->width_mm = std::max(0.1, b.width_mm());
      s->height_mm = std::max(0.1, b.height_mm());
      s->cx_mm = (b.x0_mm + b.x1_mm) / 2;
      s->cy_mm = (b.y0_mm + b.y1_mm) / 2;
      s->rx_mm = std::max(0.05, b.width_mm() / 2);
      s->ry_mm = std::max(0.05, b.height_mm() / 2);
      s->points = {{b.x0_mm, b.y0_mm}, {b.x1_mm, b.y0_mm}, {b.x1_mm, b.y1_mm}, {b.x0_mm, b.y1_mm}};
      if (s->shape != SurfaceShape::rect) s->x_mm = s->y_mm = s->width_mm = s->height_mm = 0;
      if (s->shape != SurfaceShape::ellipse) s->cx_mm = s->cy_mm = s->rx_mm = s->ry_mm = 0;
      if (s->shape != SurfaceShape::polygon) s->points.clear();
      changed = true;
    }
    if (s->shape == SurfaceShape::rect) {
      field("x##rect", s->x_mm, "mm", -kCoord, kCoord);
      field("y##rect", s->y_mm, "mm", -kCoord, kCoord);
      field("width##rect", s->width_mm, "mm", 0, kCoord, true);
      field("height##rect", s->height_mm, "mm", 0, kCoord, true);
    } else if (s->shape == SurfaceShape::ellipse) {
      field("cx", s->cx_mm, "mm", -kCoord, kCoord);
      field("cy", s->cy_mm, "mm", -kCoord, kCoord);
      field("rx", s->rx_mm, "mm", 0, kCoord, true);
      field("ry", s->ry_mm, "mm", 0, kCoord, true);
    } else {
      ImGui::Text("%zu points (x, y mm)", s->points.size());
      for (std::size_t i = 0; i < s->points.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        double xy[2] = {s->points[i].x_mm, s->points[i].y_mm};
        ImGui::SetNextItemWidth(200);
        if (ImGui::InputScalarN("##pt", ImGuiDataType_Double, xy, 2, nullptr, nullptr, "%.6g") &&
            std::isfinite(xy[0]) && std::isfinite(xy[1])) {
          s->points[i] = {std::clamp(xy[0], -kCoord, kCoord), std::clamp(xy[1], -kCoord, kCoord)};
          changed = true;
        }
        track_widget_gesture();
        if (s->points.size() > 3) {
          ImGui::SameLine();
          if (ImGui::SmallButton("-")) {
            s->points.erase(s->points.begin() + static_cast<std::ptrdiff_t>(i));
            changed = true;
            ImGui::PopID();
            break;
          }
        }
        ImGui::PopID();
      }
      if (ImGui::SmallButton("add point")) {
        const Point2Mm a = s->points.back();
        const Point2Mm b = s->points.front();
        s->points.push_back({(a.x_mm + b.x_mm) / 2, (a.y_mm + b.y_mm) / 2});
        changed = true;
      }
    }
    field("period", s->period_mm, "mm", 0, kCoord, true);
    field("relief", s->relief_mm, "mm", 0, kCoord, true);
    static constexpr const char* kPatterns[] = {"sine", "square", "triangle"};
    int pattern = static_cast<int>(s->pattern);
    ImGui::SetNextItemWidth(120);
    if (ImGui::Combo("pattern", &pattern, kPatterns, 3)) {
      s->pattern = static_cast<SurfacePattern>(pattern);
      changed = true;
    }
    field("gain##surface", s->gain, "", 0, 1);
  } else if (auto* g = std::get_if<Group>(&e.body)) {
    if (name_for_ != id || !ImGui::IsAnyItemActive()) {
      std::snprintf(name_buffer_, sizeof name_buffer_, "%s", g->name.value_or("").c_str());
      name_for_ = id;
    }
    ImGui::SetNextItemWidth(200);
    if (ImGui::InputText("name", name_buffer_, sizeof name_buffer_, ImGuiInputTextFlags_EnterReturnsTrue)) {
      g->name = name_buffer_[0] ? std::optional<std::string>(name_buffer_) : std::nullopt;
      changed = true;
    }
    ImGui::Text("%zu members", g->children.size());
    if (ImGui::Button("Ungroup (Ctrl+Shift+G)")) doc_.ungroup_selection();
  } else {
    ImGui::TextWrapped("An element this version does not know; it is kept as it is.");
  }
  // Edits while playing are heard at once: the player cross-fades to the changed scene.
  if (changed) doc_.replace_element(id, e);
}

void PropertiesPanel::draw_document() {
  Image settings = doc_.image();
  settings.children.clear();
  bool changed = false;
  auto field = [&](const char* label, double& v, const char* unit, double min, double max, bool open_min = false) {
    const FieldResult r = number_field(label, v, unit, min, max, open_min);
    changed |= r.changed;
    if (r.activated) doc_.begin_gesture();
    if (r.deactivated) doc_.end_gesture();
    layout_.print(label, r.min.x, r.min.y, r.size.x, r.size.y);
  };
  ImGui::Text("Document (select an element to edit it)");
  field("width##doc", settings.width_mm, "mm", 0, 10000, true);
  field("height##doc", settings.height_mm, "mm", 0, 10000, true);
  ImGui::Separator();
  ImGui::Text("Finger (interaction point)");
  InteractionParams ip = settings.effective_interaction();
  const InteractionParams before = ip;
  field("mass", ip.mass_kg, "kg", 0, 10, true);
  field("full speed", ip.full_speed_mm_per_s, "mm/s", 0, 100000, true);
  field("max deformation", ip.max_deformation_mm, "mm", 0, 100, true);
  if (!(ip == before)) settings.interaction = ip;
  ImGui::Separator();
  ImGui::Text("Meta");
  Meta meta = settings.meta.value_or(Meta{});
  auto text_field = [&](const char* label, std::optional<std::string>& value) {
    const int slot = static_cast<int>(std::strlen(label)) % 4;
    ImGui::PushID(label);
    const std::string current = value.value_or("");
    if (meta_shown_[slot] != current && !ImGui::IsAnyItemActive()) {
      std::snprintf(meta_buffers_[slot], sizeof meta_buffers_[slot], "%s", current.c_str());
      meta_shown_[slot] = current;
    }
    ImGui::SetNextItemWidth(220);
    if (ImGui::InputText(label, meta_buffers_[slot], sizeof meta_buffers_[slot], ImGuiInputTextFlags_EnterReturnsTrue)) {
      value = meta_buffers_[slot][0] ? std::optional<std::string>(meta_buffers_[slot]) : std::nullopt;
      changed = true;
    }
    ImGui::PopID();
  };
  text_field("title", meta.title);
  text_field("author", meta.author);
  text_field("description", meta.description);
  if (changed) {
    if (!(meta == settings.meta.value_or(Meta{})) || settings.meta) settings.meta = meta;
    doc_.replace_image_settings(settings);
  }
  ImGui::Separator();
  ImGui::TextDisabled("Canvas: %g x %g mm, %zu top-level elements", doc_.image().width_mm, doc_.image().height_mm,
                      doc_.image().children.size());
}

}  // namespace vimg::editor
