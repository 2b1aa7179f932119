// Fuzzes the volume scene reader: any bytes give located errors or a scene, never a crash; and
// every scene that parses survives the canonical writer.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "fuzz/check_messages.hpp"
#include "storage/limits.hpp"
#include "storage/volume/volume_scene_io.hpp"

using vimg::fuzz::check_messages;

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
