// Fuzzes the PNG reader (libpng behind setjmp) and the XML it carries: any bytes give an error
// message or an image, never a crash, leak or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/image_io.hpp"
#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/png_codec.hpp"

using vimg::fuzz::check_messages;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const vimg::PngText text = vimg::read_png_text(bytes);
  if (!text.error.empty() && text.xml) std::abort();  // a damaged PNG yields no text
  if (text.xml && text.xml->size() > vimg::kMaxImageFileBytes) std::abort();  // never inflated past the limit
  if (text.xml) {
    const vimg::LoadResult loaded = vimg::parse_image_xml(*text.xml, "fuzz.png");
    if (loaded.ok() == vimg::has_errors(loaded.diagnostics)) std::abort();
    check_messages(loaded.diagnostics);
  }
  return 0;
}
