// Fuzzes the PNG reader (libpng behind setjmp) and the XML it carries: any bytes give an error
// message or an image, never a crash, leak or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/image_io.hpp"
#include "storage/limits.hpp"
#include "storage/png_codec.hpp"

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
