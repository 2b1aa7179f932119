// What the hostile SVG tests share: a drawing of `count` copies of one shape, and an import's errors
// as text.
#pragma once

#include <cstddef>
#include <string>

#include "storage/import/import.hpp"

namespace vimg::test {

// 100 x 100 mm, one user unit a millimetre; `count` copies of `shape`, one a line (line n + 1).
inline std::string svg_of(std::size_t count, const std::string& shape, const std::string& head = "") {
  std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='100mm' height='100mm' viewBox='0 0 100 100'>" + head + "\n";
  svg.reserve(count * (shape.size() + 1) + 200);
  for (std::size_t i = 0; i < count; ++i) svg += shape + "\n";
  return svg + "</svg>\n";
}

inline std::string errors_of(const ImportResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) out += d.to_string() + "\n";
  }
  return out;
}

}  // namespace vimg::test
