// Fuzzes the volume scene reader: any bytes give located errors or a scene, never a crash; and
// every scene that parses survives the canonical writer.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "storage/limits.hpp"
#include "storage/volume/volume_scene_io.hpp"

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
  const vimg::VolumeSceneParseResult first = vimg::parse_volume_scene_xml(text, "fuzz.xml");
  check_messages(first.diagnostics);
  if (!first.ok()) {
    if (!vimg::has_errors(first.diagnostics)) std::abort();  // a rejection always says why
    return 0;
  }
  const auto second = vimg::parse_volume_scene_xml(vimg::write_volume_scene_xml(*first.scene), "w.xml");
  if (!second.ok()) std::abort();  // the writer wrote a scene its own reader rejects
  return 0;
}
