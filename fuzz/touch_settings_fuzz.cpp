// Fuzzes the touch-latency settings parser (storage/touch_settings_file.hpp): any bytes give
// settings within their bounds and messages that name a line of the input, never a crash.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "primitives/touch_prediction/touch_latency_defaults.hpp"
#include "storage/touch_settings_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::TouchSettingsRead read = vimg::parse_touch_settings(text, "fuzz.txt");
  if (const auto& ms = read.settings.latency_ms; ms && !(*ms >= 0.0 && *ms <= vimg::kMaxTouchPanelLatency_s * 1e3)) std::abort();
  std::size_t lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  for (const vimg::Diagnostic& d : read.diagnostics) {
    const bool count_of_the_rest = d.not_shown_errors + d.not_shown_warnings > 0;  // line 0
    if ((d.line < 1 && !count_of_the_rest) || static_cast<std::size_t>(d.line) > lines) std::abort();
    if (d.to_string().find('\n') != std::string::npos) std::abort();
  }
  return 0;
}
