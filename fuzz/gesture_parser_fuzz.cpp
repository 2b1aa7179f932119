// Fuzzes the gesture CSV parser: any bytes give located errors or a gesture, never a crash; and
// every gesture that parses survives its own writer.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "storage/gesture_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const vimg::GestureParseResult first = vimg::parse_gesture_csv(text, "fuzz.csv");
  if (!first.ok()) {
    if (first.errors.empty()) std::abort();  // a rejection always says why, and where
    for (const auto& e : first.errors) {
      if (!e.starts_with("fuzz.csv:")) std::abort();
    }
    return 0;
  }
  const vimg::GestureParseResult second = vimg::parse_gesture_csv(vimg::write_gesture_csv(*first.gesture), "w.csv");
  if (!second.ok()) std::abort();  // the writer wrote a file its own parser rejects
  if (second.gesture->strokes.size() != first.gesture->strokes.size()) std::abort();
  return 0;
}
