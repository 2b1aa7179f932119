// Fuzzes the DRV2605L calibration file parser: any bytes give a calibration within the chip's
// ranges or a located error, never a crash.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/drv2605l_calibration_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::CalibrationLoadResult r = vimg::parse_calibration(text, "fuzz.cal");
  if (r.calibration.has_value() == !r.error().empty()) std::abort();  // one or the other
  if (r.calibration) {
    if (!(r.calibration->resonance_hz > 0.0) || !std::isfinite(r.calibration->resonance_hz)) std::abort();
    if (r.calibration->bemf_gain > 3) std::abort();
  } else if (r.error().rfind("fuzz.cal:", 0) != 0) {
    std::abort();  // every error names the file
  }
  return 0;
}
