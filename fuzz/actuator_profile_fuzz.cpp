// Fuzzes the actuator profile reader: any bytes give located errors or a profile, never a crash;
// a profile that loads gives a response model whose output stays finite and bounded (the ranges
// the reader enforces are enough for a stable filter at every render rate).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/actuator_profile.hpp"
#include "primitives/actuator/actuator_chain.hpp"

namespace {

// A unit step then a full-scale square wave: the model's output must stay finite and, since its
// peak gain is 0 dB, within a bounded overshoot.
void check_model(const vimg::ResponseParams& params, double rate_hz) {
  vimg::ActuatorChain chain(params, rate_hz, vimg::OutputSignal::acceleration, true);
  for (int n = 0; n < 512; ++n) {
    const float x = n < 256 ? 1.0f : ((n / 7) % 2 == 0 ? 1.0f : -1.0f);
    const float y = chain.process(x);
    if (!std::isfinite(y) || std::fabs(y) > 8.0f) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::ProfileLoadResult result = vimg::parse_actuator_profile(text, "fuzz.xml");
  if (result.profile.has_value() != result.errors.empty()) std::abort();  // a profile iff no error
  for (const auto& e : result.errors) {
    if (!e.starts_with("fuzz.xml")) std::abort();  // every message names the file
  }
  if (result.profile) {
    for (const double rate_hz : {1.0, 8000.0, 48000.0}) check_model(result.profile->response, rate_hz);
  }
  return 0;
}
