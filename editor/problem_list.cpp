// The inspector's problem list (problem_list.hpp).
#include "editor/problem_list.hpp"

#include <imgui.h>

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
}

void ProblemList::draw(float x, float y, float w, float h, const std::vector<Diagnostic>& load_diagnostics) const {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::Begin("Validation", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  if (diagnostics_.empty() && load_diagnostics.empty()) {
    ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "The image is valid.");
  }
  for (const auto* list : {&load_diagnostics, &diagnostics_}) {
    for (const Diagnostic& d : *list) {
      const ImVec4 colour = d.severity == Diagnostic::Severity::error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f)
                                                                      : ImVec4(1.0f, 0.85f, 0.4f, 1.0f);
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      ImGui::TextWrapped("%s", d.to_string().c_str());
      ImGui::PopStyleColor();
    }
  }
  ImGui::End();
}

}  // namespace vimg::editor
