#pragma once
// A message about a file: `FILE:LINE: error: problem` or `FILE:LINE: warning: problem`.
#include <string>
#include <vector>

namespace vimg {

struct Diagnostic {
  enum class Severity { error, warning };
  Severity severity = Severity::error;
  std::string file;   // as the user named it
  int line = 0;       // 1-based; 0 when the problem is not tied to a line (e.g. I/O errors)
  std::string message;

  // "FILE:LINE: error: message" (spec section 4); "FILE: error: message" when line is 0.
  std::string to_string() const;
};

bool has_errors(const std::vector<Diagnostic>& diagnostics);

}  // namespace vimg
