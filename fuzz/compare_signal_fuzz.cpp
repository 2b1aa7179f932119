// Fuzzes the rendered-signal readers of vimg compare (storage/signal_file.hpp): any bytes, read as
// a WAV and as a render CSV, give a located error or samples, never a crash; samples are finite,
// at most kMaxSignalDurationS at 8 kHz, and never none.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/limits.hpp"
#include "storage/signal_file.hpp"

namespace {

void check(const vimg::SignalReadResult& r, std::string_view file) {
  if (!r.ok()) {
    if (r.diagnostics.empty()) std::abort();  // a rejection always says why
    for (const auto& d : r.diagnostics) {
      if (d.file != file || d.severity != vimg::Diagnostic::Severity::error) std::abort();
    }
    return;
  }
  if (r.samples->empty()) std::abort();
  if (static_cast<double>(r.samples->size()) > vimg::kMaxSignalDurationS * vimg::kCompareRateHz) std::abort();
  for (const float v : *r.samples) {
    if (!std::isfinite(v)) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  check(vimg::parse_wav_signal(bytes, "fuzz.wav"), "fuzz.wav");
  check(vimg::parse_csv_signal(bytes, "fuzz.csv"), "fuzz.csv");
  return 0;
}
