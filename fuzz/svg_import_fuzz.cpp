// Fuzzes SVG import (storage/import): any bytes give an image or errors, never a crash, leak or
// undefined behaviour; messages are printable and bounded; and an imported image is one that
// `vimg validate` accepts (it reads back without errors).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/check_import.hpp"
#include "storage/import/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  vimg::fuzz::check_import(vimg::import_svg(text, "fuzz.svg", {}));
  return 0;
}
