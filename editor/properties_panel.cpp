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
#include "storage/number_text.hpp"
#include "storage/palette.hpp"
#include "storage/parameter_table.hpp"

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

// The name scripts find a field by in the layout log: the attribute's name, with "##" and the
// element when another element has an attribute of that name ("radius", "width##line").
std::string layout_name(const ParameterSpec& spec) {
  for (const ParameterSpec& other : parameter_table()) {
    if (&other != &spec && other.name == spec.name) return std::string(spec.name) + "##" + std::string(owner_tag(spec.owner));
  }
  return std::string(spec.name);
}

// What the parameter table says of an attribute: its meaning, range, unit and default.
std::string help_text(const ParameterSpec& spec) {
  std::string text = std::string(spec.meaning) + ".\nrange " + interval_text(spec);
  if (spec.unit != "1") text += " " + std::string(spec.unit);
  text += spec.required ? ", required" : ", default " + format_decimal(spec.default_value);
  return text;
}

// A number field as the parameter table describes it (storage/parameter_table.hpp): the unit in the
// label, the range beside it, the meaning as its tooltip. A typed value is clamped into the range;
// a value read out of range (a file with problems) is shown in red until it is changed or clamped.
FieldResult number_field(const ParameterSpec& spec, double& value) {
  FieldResult r;
  double v = value;
  const std::string unit = spec.unit == "1" ? "" : " (" + std::string(spec.unit) + ")";
  const std::string label = std::string(spec.name) + unit + "##" + std::string(owner_tag(spec.owner));
  const bool outside = !in_range(spec, value);
  ImGui::SetNextItemWidth(120);
  if (outside) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.55f, 0.12f, 0.12f, 1.0f));
  const bool edited = ImGui::InputDouble(label.c_str(), &v, 0.0, 0.0, "%.6g");
  if (outside) ImGui::PopStyleColor();
  r.activated = ImGui::IsItemActivated();
  r.deactivated = ImGui::IsItemDeactivated();
  r.min = ImGui::GetItemRectMin();
  r.size = ImGui::GetItemRectSize();
  const bool hovered = ImGui::IsItemHovered();
  ImGui::SameLine();
  if (outside) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "outside %s", interval_text(spec).c_str());
  } else {
    ImGui::TextDisabled("%s", interval_text(spec).c_str());
  }
  if (hovered || ImGui::IsItemHovered()) ImGui::SetTooltip("%s", help_text(spec).c_str());
  if (!edited || !std::isfinite(v)) return r;
  v = clamp_to_range(spec, v);
  if (v == value) return r;
  value = v;
  r.changed = true;
  return r;
}

// A choice of the parameter table as a combo box; `index` is the word's place in `choices` (the
// model's enumerations follow the table's order).
bool choice_field(const ParameterSpec& spec, int& index) {
  std::string items;
  for (const char c : spec.choices) items += c == '|' ? '\0' : c;
  items += '\0';
  items += '\0';
  ImGui::SetNextItemWidth(120);
  const std::string label = std::string(spec.name) + "##" + std::string(owner_tag(spec.owner));
  const bool changed = ImGui::Combo(label.c_str(), &index, items.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(spec.meaning).c_str());
  return changed;
}

ParameterOwner owner_of(const Element& e) {
  if (std::holds_alternative<Line>(e.body)) return ParameterOwner::line;
  if (std::holds_alternative<Surface>(e.body)) return ParameterOwner::surface;
  return ParameterOwner::dot;
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
  auto field = [&](const ParameterSpec& spec, double& v) {
    const FieldResult r = number_field(spec, v);
    changed |= r.changed;
    if (r.activated) doc_.begin_gesture();
    if (r.deactivated) doc_.end_gesture();
    layout_.print(layout_name(spec), r.min.x, r.min.y, r.size.x, r.size.y);
  };

  ImGui::Text("%s", kind_name(e).c_str());
  if (const FeltMark* weak = feel_ ? feel_->mark_of(id) : nullptr) {
    const palette::Rgb8 c = palette::kWeakOnActuator;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f));
    ImGui::TextWrapped("warning: %s", weak->message.c_str());
    ImGui::PopStyleColor();
    layout_.print("feel_warning", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                  ImGui::GetItemRectSize().y);
  }
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
  if (std::holds_alternative<Dot>(e.body) || std::holds_alternative<Line>(e.body) ||
      std::holds_alternative<Surface>(e.body)) {
    // Every attribute in the parameter table's order.
    const ParameterOwner owner = owner_of(e);
    for (const ParameterSpec& spec : parameter_table()) {
      if (spec.owner != owner) continue;
      auto* s = std::get_if<Surface>(&e.body);
      if (s != nullptr && !applies_to_shape(spec, s->shape)) continue;
      switch (spec.kind) {
        case ParameterKind::number: field(spec, *number_in(e, spec)); break;
        case ParameterKind::choice:
          if (spec.name == "shape") {
            changed |= shape_field(spec, e);
          } else {
            int pattern = static_cast<int>(s->pattern);
            if (choice_field(spec, pattern)) {
              s->pattern = static_cast<SurfacePattern>(pattern);
              changed = true;
            }
          }
          break;
        case ParameterKind::points: changed |= points_field(*s); break;
        case ParameterKind::id:
        case ParameterKind::text:
        case ParameterKind::version: break;  // the id is above
      }
    }
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

bool PropertiesPanel::shape_field(const ParameterSpec& spec, Element& e) {
  auto& s = std::get<Surface>(e.body);
  int shape = static_cast<int>(s.shape);
  if (!choice_field(spec, shape)) return false;
  // Keep the same place and size in the new shape.
  const RectMm b = element_bounds(e).value_or(RectMm{0, 0, 10, 10});
  s.shape = static_cast<SurfaceShape>(shape);
  s.x_mm = b.x0_mm;
  s.y_mm = b.y0_mm;
  s.width_mm = std::max(0.1, b.width_mm());
  s.height_mm = std::max(0.1, b.height_mm());
  s.cx_mm = (b.x0_mm + b.x1_mm) / 2;
  s.cy_mm = (b.y0_mm + b.y1_mm) / 2;
  s.rx_mm = std::max(0.05, b.width_mm() / 2);
  s.ry_mm = std::max(0.05, b.height_mm() / 2);
  s.points = {{b.x0_mm, b.y0_mm}, {b.x1_mm, b.y0_mm}, {b.x1_mm, b.y1_mm}, {b.x0_mm, b.y1_mm}};
  if (s.shape != SurfaceShape::rect) s.x_mm = s.y_mm = s.width_mm = s.height_mm = 0;
  if (s.shape != SurfaceShape::ellipse) s.cx_mm = s.cy_mm = s.rx_mm = s.ry_mm = 0;
  if (s.shape != SurfaceShape::polygon) s.points.clear();
  return true;
}

bool PropertiesPanel::points_field(Surface& s) {
  bool changed = false;
  ImGui::Text("%zu points (x, y mm)", s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    double xy[2] = {s.points[i].x_mm, s.points[i].y_mm};
    ImGui::SetNextItemWidth(200);
    if (ImGui::InputScalarN("##pt", ImGuiDataType_Double, xy, 2, nullptr, nullptr, "%.6g") && std::isfinite(xy[0]) &&
        std::isfinite(xy[1])) {
      s.points[i] = {xy[0], xy[1]};
      changed = true;
    }
    track_widget_gesture();
    if (s.points.size() > 3) {
      ImGui::SameLine();
      if (ImGui::SmallButton("-")) {
        s.points.erase(s.points.begin() + static_cast<std::ptrdiff_t>(i));
        ImGui::PopID();
        return true;
      }
    }
    ImGui::PopID();
  }
  if (ImGui::SmallButton("add point")) {
    const Point2Mm a = s.points.back();
    const Point2Mm b = s.points.front();
    s.points.push_back({(a.x_mm + b.x_mm) / 2, (a.y_mm + b.y_mm) / 2});
    changed = true;
  }
  return changed;
}

void PropertiesPanel::draw_document() {
  Image settings = doc_.image();
  settings.children.clear();
  bool changed = false;
  auto fields = [&](ParameterOwner owner) {
    for (const ParameterSpec& spec : parameter_table()) {
      if (spec.owner != owner || spec.kind != ParameterKind::number) continue;
      const FieldResult r = number_field(spec, *number_in(settings, spec));
      changed |= r.changed;
      if (r.activated) doc_.begin_gesture();
      if (r.deactivated) doc_.end_gesture();
      layout_.print(layout_name(spec), r.min.x, r.min.y, r.size.x, r.size.y);
    }
  };
  ImGui::Text("Document (select an element to edit it)");
  fields(ParameterOwner::canvas);
  ImGui::Separator();
  ImGui::Text("Finger (interaction point)");
  const bool had_interaction = settings.interaction.has_value();
  settings.interaction = settings.effective_interaction();
  fields(ParameterOwner::interaction);
  // Absent means the defaults, and stays absent until a value is changed.
  if (!had_interaction && *settings.interaction == InteractionParams{}) settings.interaction.reset();
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
