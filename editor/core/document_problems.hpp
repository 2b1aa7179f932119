#pragma once
// A document with problems, for the editor: opening a file that has errors with every element that
// could be read (LoadResult::readable), finding the numbers outside their range (the parameter
// table's ranges) with a fix for each, and one list of problems in which each problem appears once.
// No GUI code.
#include <optional>
#include <string>
#include <vector>

#include "primitives/image.hpp"
#include "storage/diagnostic.hpp"
#include "storage/image_io.hpp"
#include "storage/parameter_table.hpp"

namespace vimg::editor {

// A number outside its range and where it is: the element `element_id` (a dot, line or surface,
// inside groups too), or the document itself (canvas size, <interaction>) when the id is empty.
struct ClampFix {
  std::string element_id;
  const ParameterSpec* parameter = nullptr;
  double value = 0.0;  // as it is now
  friend bool operator==(const ClampFix&, const ClampFix&) = default;
};

// What the editor opens: the image (valid or as far as it could be read) with every known element
// named (missing ids given, duplicate ids renamed in document order), and the reader's diagnostics.
struct OpenedDocument {
  Image image;
  std::vector<Diagnostic> diagnostics;
  std::vector<ValueProblem> value_problems;  // the reader's, in file order
  bool has_errors() const { return vimg::has_errors(diagnostics); }
};

// The document to open from a load result, or nothing when the file cannot be read at all
// (malformed XML, another root, another major version, an unreadable canvas size, I/O errors).
std::optional<OpenedDocument> open_document_with_problems(LoadResult result);

// Every number of the image outside its range, in document order (the document's own first).
std::vector<ClampFix> find_out_of_range(const Image& image);

// The message of a fix: "dot c: gain 3 is outside [0, 1]".
std::string describe(const ClampFix& fix);

// One entry of the problem list.
struct Problem {
  Diagnostic::Severity severity = Diagnostic::Severity::error;
  std::string text;                // without the file name; "line N: " (or "lines N, M: ") first when known
  std::optional<ClampFix> fix;     // a number out of range: the list offers to clamp it
};

// The problem list: the numbers out of range in the image now (each with its fix), then the
// reader's other diagnostics (with the file's lines), then the diagnostics of a later check (`live`,
// e.g. of the canonical text; no lines, they are not the file's) that say something not said above.
// Out-of-range messages of the reader and of `live` are left out: the image's own values are the
// list's (a value left out with an unreadable element goes with that element's error). Identical
// messages appear once, naming all their lines. Costs a pass over the image: cache it per change.
std::vector<Problem> problem_list(const Image& image, const std::vector<Diagnostic>& load_diagnostics,
                                  const std::vector<Diagnostic>& live);

}  // namespace vimg::editor
