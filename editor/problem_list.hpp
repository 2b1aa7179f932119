#pragma once
// The inspector's problem list: each problem of the document once (editor/core/document_problems.hpp):
// the numbers out of range, each with a "clamp" button, and "Clamp all" for all of them in one undo
// step; then the problems found when the file was opened, with the file's lines; then what a reader
// reports of the document as it is now (the canonical XML written and parsed back, 0.3 s after the
// last edit) that is not said above. GUI thread.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "editor/core/document_editor.hpp"
#include "editor/core/document_problems.hpp"
#include "storage/diagnostic.hpp"

namespace vimg::editor {

class LayoutLog;

class ProblemList {
 public:
  // Validates the document again once it has changed and editing pauses. `name`: the file name
  // the messages carry.
  void refresh(const DocumentEditor& doc, const std::string& name, double now_s);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  // Draws the list; its buttons clamp values of `doc`.
  void draw(float x, float y, float w, float h, DocumentEditor& doc, const std::vector<Diagnostic>& load_diagnostics,
            LayoutLog& layout);

 private:
  // The list for the document now, rebuilt when the document, the load problems or the check change.
  const std::vector<Problem>& problems(const DocumentEditor& doc, const std::vector<Diagnostic>& load_diagnostics);

  std::vector<Diagnostic> diagnostics_;
  std::uint64_t validated_change_ = ~0ull;
  double validation_due_s_ = 0.0;
  std::uint64_t checks_ = 0;  // how many times diagnostics_ was replaced
  std::vector<Problem> problems_;
  struct Key {
    const Image* image = nullptr;
    std::uint64_t change = ~0ull;
    const Diagnostic* load = nullptr;
    std::size_t load_size = 0;
    std::uint64_t checks = ~0ull;
    bool operator==(const Key&) const = default;
  } listed_;
};

}  // namespace vimg::editor
