#pragma once
// How every program reports a file's problems: each diagnostic on a line of its own
// ("FILE:LINE: error: problem", Diagnostic::to_string), on stderr unless the command's output is
// the report itself (vimg validate prints to stdout).
#include <cstdio>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

void print_diagnostics(const std::vector<Diagnostic>& diagnostics, std::FILE* out = stderr);

}  // namespace vimg
