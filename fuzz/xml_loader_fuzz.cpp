// Fuzzes the XML image loader: any bytes give diagnostics or an image, never a crash, leak or
// undefined behaviour; and every image that loads survives the canonical round trip.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/image_io.hpp"
#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"

using vimg::fuzz::check_messages;

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
