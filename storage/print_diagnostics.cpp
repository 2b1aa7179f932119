#include "storage/print_diagnostics.hpp"

namespace vimg {

void print_diagnostics(const std::vector<Diagnostic>& diagnostics, std::FILE* out) {
  for (const Diagnostic& d : diagnostics) std::fprintf(out, "%s\n", d.to_string().c_str());
}

}  // namespace vimg
