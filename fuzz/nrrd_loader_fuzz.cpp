// Fuzzes the NRRD volume loader: any bytes give diagnostics or a grid, never a crash, leak or
// undefined behaviour; a grid that loads is complete, samples finitely and survives a round trip.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/volume/nrrd.hpp"

using vimg::fuzz::check_messages;

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
