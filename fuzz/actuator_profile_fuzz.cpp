// Fuzzes the actuator profile reader: any bytes give located errors or a profile, never a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hal/actuator_profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::ProfileLoadResult result = vimg::parse_actuator_profile(text, "fuzz.xml");
  if (result.profile.has_value() != result.errors.empty()) std::abort();  // a profile iff no error
  for (const auto& e : result.errors) {
    if (!e.starts_with("fuzz.xml")) std::abort();  // every message names the file
  }
  return 0;
}
