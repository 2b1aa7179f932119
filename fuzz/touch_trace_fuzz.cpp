// Fuzzes the touch-recording reader (evemu-record and getevent text): any bytes give located
// diagnostics or a trace, never a crash, leak or undefined behaviour; a trace is well formed
// (each contact a down, moves and an up, times never decreasing, fingers within the gesture's
// range), and the gesture made of it is one the gesture parser reads back.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fuzz/check_messages.hpp"
#include "storage/gesture_csv.hpp"
#include "player/touch_trace_gesture.hpp"
#include "storage/touch_trace/evdev_trace.hpp"

using vimg::fuzz::check_messages;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::TouchTraceParseResult r = vimg::parse_touch_trace(text, "fuzz.evemu");
  check_messages(r.diagnostics);
  if (r.trace.has_value() == vimg::has_errors(r.diagnostics)) std::abort();  // a trace iff no error
  if (!r.trace) return 0;
  for (const vimg::TouchContact& c : r.trace->contacts) {
    if (c.finger < 0 || c.finger > vimg::kMaxGestureFinger || c.samples.size() < 2) std::abort();
    if (c.samples.front().phase != vimg::TouchSample::Phase::down) std::abort();
    if (c.samples.back().phase != vimg::TouchSample::Phase::up) std::abort();
    for (std::size_t i = 1; i < c.samples.size(); ++i) {
      if (c.samples[i].time_s < c.samples[i - 1].time_s) std::abort();
    }
  }
  vimg::TouchMapping mapping;
  mapping.units_per_mm = 1.0;
  const vimg::TraceGestureResult g = vimg::trace_to_gesture(*r.trace, mapping, "fuzz.evemu");
  if (!g.gesture) {
    if (g.errors.empty()) std::abort();
    return 0;
  }
  const vimg::GestureParseResult back = vimg::parse_gesture_csv(vimg::write_gesture_csv(*g.gesture), "g.csv");
  if (!back.ok()) std::abort();
  return 0;
}
