// Fuzzes the --output SPEC parser (audio, wav:FILE, drv2605l:BUS[,...], spi:..., hid:VID:PID):
// any text gives a spec or an error message, never both, never a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "hal/output_spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const vimg::OutputParseResult r = vimg::parse_output_spec(text);
  if (r.spec.has_value() == !r.error.empty()) std::abort();
  return 0;
}
