// Fuzzes the NRRD volume loader: any bytes give diagnostics or a grid, never a crash, leak or
// undefined behaviour; a grid that loads is complete, samples finitely and survives a round trip.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/limits.hpp"
#include "storage/volume/nrrd.hpp"

namespace {

// Every message is printable (no control character reaches a terminal) and bounded, at most
// kMaxDiagnosticsPerFile of them plus the line counting the rest.
void check_messages(const std::vector<vimg::Diagnostic>& diagnostics) {
  if (diagnostics.size() > vimg::kMaxDiagnosticsPerFile + 1) std::abort();
  for (const auto& d : diagnostics) {
    if (d.message.size() > vimg::kMaxMessageBytes) std::abort();
    for (const char c : d.to_string()) {
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const vimg::NrrdLoadResult r = vimg::parse_nrrd(bytes, "fuzz.nrrd");
  if (r.ok() == vimg::has_errors(r.diagnostics)) std::abort();  // a grid iff no error
  check_messages(r.diagnostics);
  if (r.scalar && r.vector) std::abort();
  if (r.scalar) {
    if (r.scalar->empty()) std::abort();
    const vimg::GridGeometry& g = r.scalar->geometry();
    const vimg::Vec3 mid = (g.origin_m + g.far_corner_m()) * 0.5;
    if (!std::isfinite(r.scalar->value(mid))) std::abort();
    const vimg::NrrdLoadResult again = vimg::parse_nrrd(vimg::write_nrrd(*r.scalar, vimg::NrrdEncoding::raw), "again.nrrd");
    if (!again.scalar || again.scalar->values() != r.scalar->values()) std::abort();
  }
  if (r.vector && r.vector->empty()) std::abort();
  return 0;
}
