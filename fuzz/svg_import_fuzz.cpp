// Fuzzes SVG import (storage/import): any bytes give an image or errors, never a crash, leak or
// undefined behaviour; messages are printable and bounded; and an imported image is one that
// `vimg validate` accepts (it reads back without errors).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz/check_messages.hpp"
#include "storage/image_io.hpp"
#include "storage/import/import.hpp"

using vimg::fuzz::check_messages;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::ImportResult r = vimg::import_svg(text, "fuzz.svg", {});
  if (r.ok() == vimg::has_errors(r.diagnostics)) std::abort();
  check_messages(r.diagnostics);
  if (r.image) {
    const vimg::LoadResult back = vimg::parse_image_xml(vimg::write_image_xml(*r.image), "fuzz.vimg");
    if (!back.ok()) std::abort();
  }
  return 0;
}
