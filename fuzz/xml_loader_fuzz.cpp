// Fuzzes the XML image loader: any bytes give diagnostics or an image, never a crash, leak or
// undefined behaviour; and every image that loads survives the canonical round trip.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"

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
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::LoadResult first = vimg::parse_image_xml(text, "fuzz.vimg");
  if (first.ok() == vimg::has_errors(first.diagnostics)) std::abort();  // image iff no error
  check_messages(first.diagnostics);
  if (!first.ok()) return 0;
  const std::string canonical = vimg::write_image_xml(*first.image);
  const vimg::LoadResult second = vimg::parse_image_xml(canonical, "canonical.vimg");
  if (!second.ok()) std::abort();                                     // the writer wrote an invalid file
  if (vimg::write_image_xml(*second.image) != canonical) std::abort();  // canonical form is stable
  return 0;
}
