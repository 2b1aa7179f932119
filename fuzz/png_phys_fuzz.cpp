// Fuzzes the reading of a PNG's pHYs chunk (File -> Import's default picture width):
// any bytes give nothing or a width in (0, kMaxCanvasMm] mm, never a read past the end or a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/png_codec.hpp"
#include "storage/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const auto width_mm = vimg::png_physical_width_mm(bytes);
  if (width_mm && !(*width_mm > 0.0 && *width_mm <= vimg::kMaxCanvasMm)) std::abort();
  return 0;
}
