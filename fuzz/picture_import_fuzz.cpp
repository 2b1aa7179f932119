// Fuzzes picture import (PNG through libpng, marching squares, simplification, hole bridging) on
// small inputs: any bytes give an image of SURFACE polygons or an error, never a crash, leak or
// undefined behaviour; an imported image reads back without errors.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/check_import.hpp"
#include "storage/import/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  vimg::ImportOptions options;
  options.width_mm = 50.0;
  options.levels = 5;
  options.max_pixels = 65536;  // small pictures: a fuzzing run explores the code, not the size
  vimg::fuzz::check_import(vimg::import_picture(bytes, "fuzz.png", options));
  return 0;
}
