// The inspector's problem list (problem_list.hpp).
#include "editor/problem_list.hpp"

#include <imgui.h>

#include "editor/core/layout_log.hpp"
#include "storage/image_io.hpp"

namespace vimg::editor {

void ProblemList::refresh(const DocumentEditor& doc, const std::string& name, double now_s) {
  if (validated_change_ == doc.change_count()) return;
  if (validation_due_s_ == 0.0) validation_due_s_ = now_s + 0.3;  // wait for a pause in editing
  if (now_s < validation_due_s_ || doc.in_gesture()) return;
  validation_due_s_ = 0.0;
  validated_change_ = doc.change_count();
  // Check the document exactly as a reader will: write it canonically and read it back.
  LoadResult result = parse_image_xml(write_image_xml(doc.image()), name);
  diagnostics_ = result.diagnostics;
  ++checks_;
}

const std::vector<Problem>& ProblemList::problems(const DocumentEditor& doc,
                                                  const std::vector<Diagnostic>& load_diagnostics) {
  const Key key{&doc.image(), doc.change_count(), load_diagnostics.data(), load_diagnostics.size(), checks_};
  if (!(key == listed_)) {
    problems_ = problem_list(doc.image(), load_diagnostics, diagnostics_);
    listed_ = key;
  }
  return problems_;
}

void ProblemList::draw(float x, float y, float w, float h, DocumentEditor& doc,
                       const std::vector<Diagnostic>& load_diagnostics, LayoutLog& layout) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Problems", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  const std::vector<Problem>& list = problems(doc, load_diagnostics);
  if (list.empty()) ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "The image is valid.");
  std::vector<ClampFix> fixes;
  for (const Problem& p : list) {
    if (p.fix) fixes.push_back(*p.fix);
  }
  std::vector<ClampFix> chosen;
  if (!fixes.empty()) {
    const std::string label = "Clamp all to range (" + std::to_string(fixes.size()) + ")";
    if (ImGui::Button(label.c_str())) chosen = fixes;
    layout.print("clamp_all", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y, ImGui::GetItemRectSize().x,
                 ImGui::GetItemRectSize().y);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Moves every value into its range: one step, Ctrl+Z undoes it");
  }
  int index = 0;
  for (const Problem& p : list) {
    ImGui::PushID(index++);
    if (p.fix) {
      if (ImGui::SmallButton("clamp")) chosen = {*p.fix};
      if (ImGui::IsItemHovered()) {
        const double to = clamp_to_range(*p.fix->parameter, p.fix->value);
        ImGui::SetTooltip("Set %s to %g, the nearest value in range", std::string(p.fix->parameter->name).c_str(), to);
      }
      ImGui::SameLine();
    }
    const ImVec4 colour = p.severity == Diagnostic::Severity::error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f)
                                                                    : ImVec4(1.0f, 0.85f, 0.4f, 1.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", p.text.c_str());
    ImGui::PopStyleColor();
    layout.print("problem" + std::to_string(index - 1), ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                 ImGui::GetItemRectSize().x, ImGui::GetItemRectSize().y);
    ImGui::PopID();
  }
  ImGui::End();
  if (!chosen.empty()) doc.clamp_values(chosen);
}

}  // namespace vimg::editor
