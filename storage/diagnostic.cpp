#include "storage/diagnostic.hpp"

#include <algorithm>

namespace vimg {

std::string Diagnostic::to_string() const {
  std::string text = file;
  if (line > 0) {
    text += ':';
    text += std::to_string(line);
  }
  text += severity == Severity::error ? ": error: " : ": warning: ";
  text += message;
  return text;
}

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::error; });
}

}  // namespace vimg
