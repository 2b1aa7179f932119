#pragma once
// What every reader of a JSON document (storage/json_reader.hpp) does with the value it got: check a
// member's kind, and stop at the first problem with `FILE:LINE: error: ...` at the value's line.
// Readers derive from it (storage/study/predicted_confusion.cpp, perception_model_file.cpp).
#include <string>
#include <vector>

#include "storage/diagnostic.hpp"
#include "storage/json_reader.hpp"

namespace vimg {

class JsonChecker {
 public:
  explicit JsonChecker(const std::string& file_name) : list_(file_name) {}

  // Records the error; always false, so that a check reads `return fail(...)`.
  bool fail(int line, const std::string& message) {
    list_.error(line, message);
    return false;
  }

  // "WHAT must be an array, not a string" unless `v` is of `kind`.
  bool expect(const JsonValue& v, JsonValue::Kind kind, const std::string& what) {
    if (v.kind == kind) return true;
    return fail(v.line, what + " must be " + std::string(json_kind_name(kind)) + ", not " + std::string(json_kind_name(v.kind)));
  }

  std::vector<Diagnostic> take() { return list_.take(); }

 private:
  DiagnosticList list_;
};

}  // namespace vimg
