// Fuzzes the PNG reader (libpng behind setjmp) and the XML it carries: any bytes give an error
// message or an image, never a crash, leak or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/image_io.hpp"
#include "storage/png_codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const vimg::PngText text = vimg::read_png_text(bytes);
  if (!text.error.empty() && text.xml) std::abort();  // a damaged PNG yields no text
  if (text.xml) {
    const vimg::LoadResult loaded = vimg::parse_image_xml(*text.xml, "fuzz.png");
    if (loaded.ok() == vimg::has_errors(loaded.diagnostics)) std::abort();
  }
  return 0;
}
