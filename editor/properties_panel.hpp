#pragma once
// The inspector's properties panel: every attribute of the single selected element as the parameter
// table describes it (storage/parameter_table.hpp: unit in the label, range beside the field, the
// meaning as its tooltip), or, with nothing selected, the document's size, finger parameters and meta.
// Each widget interaction is one undo step (a gesture of the DocumentEditor). GUI thread.
#include <string>

#include "editor/core/actuator_feel.hpp"
#include "editor/core/document_editor.hpp"
#include "storage/parameter_table.hpp"
#include "editor/notices.hpp"

namespace vimg::editor {

class LayoutLog;

class PropertiesPanel {
 public:
  PropertiesPanel(DocumentEditor& doc, Notices& notices, LayoutLog& layout);
  void draw(float x, float y, float w, float h);
  // The actuator the editor designs for: a selected primitive that is weak on it shows the warning.
  void set_feel(const ActuatorFeel* feel) { feel_ = feel; }

 private:
  void draw_element(const std::string& id);
  void draw_document();
  // The shape of a surface (keeping its place and size) and a polygon's points; true when changed.
  bool shape_field(const ParameterSpec& spec, Element& e);
  bool points_field(Surface& s);
  // Brackets the last widget's interaction into one undo step.
  void track_widget_gesture();

  DocumentEditor& doc_;
  const ActuatorFeel* feel_ = nullptr;
  Notices& notices_;
  LayoutLog& layout_;
  // Text being typed, kept while its widget is active.
  char id_buffer_[128] = {};
  std::string id_for_;
  char name_buffer_[256] = {};
  std::string name_for_;
  char meta_buffers_[4][512] = {};
  std::string meta_shown_[4];
};

}  // namespace vimg::editor
