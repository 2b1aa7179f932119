#pragma once
// The inspector's problem list: the document's errors and warnings as a reader would report
// them (the canonical XML written and parsed back, 0.3 s after the last edit), after the problems
// found when the file was opened. GUI thread.
#include <cstdint>
#include <string>
#include <vector>

#include "editor/core/document_editor.hpp"
#include "storage/diagnostic.hpp"

namespace vimg::editor {

class ProblemList {
 public:
  // Validates the document again once it has changed and editing pauses. `name`: the file name
  // the messages carry.
  void refresh(const DocumentEditor& doc, const std::string& name, double now_s);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  void draw(float x, float y, float w, float h, const std::vector<Diagnostic>& load_diagnostics) const;

 private:
  std::vector<Diagnostic> diagnostics_;
  std::uint64_t validated_change_ = ~0ull;
  double validation_due_s_ = 0.0;
};

}  // namespace vimg::editor
