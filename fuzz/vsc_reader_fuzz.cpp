// Fuzzes the compact compiled image reader (storage/vsc/vsc_image.hpp), the one parser of the wasm
// renderer: any bytes give an error at a byte offset or an image that compiles into a scene and
// writes back to the very same bytes (nothing the reader accepts is lost or invented).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "player/scene.hpp"
#include "storage/vsc/vsc_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const vimg::VscReadResult r = vimg::read_vsc(bytes, "fuzz.vsc");
  if (!r.image) {
    if (!r.error.starts_with("fuzz.vsc: error: byte ")) std::abort();  // a rejection says where
    return 0;
  }
  if (vimg::write_vsc(*r.image) != bytes) std::abort();
  if (vimg::compile_scene(r.image->image) == nullptr) std::abort();
  return 0;
}
