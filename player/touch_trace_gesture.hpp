#pragma once
// A touch recording (storage/touch_trace/evdev_trace.hpp) as a gesture: digitizer units become
// millimetres, contacts become strokes (finger = slot, or the finger the protocol-A reader gave).
// The mapping, in order of preference:
//   - panel size W x H mm: x_mm = (x - x_min) / (x_max - x_min) * W, with the recording's axis
//     ranges (or ranges given by the caller);
//   - K digitizer units per mm: x_mm = (x - x_min) / K (x_min = 0 when the range is unknown);
//   - the device's own resolution (evemu's `Resolution`, units per mm) when it gives one.
// Pressure becomes (p - p_min) / (p_max - p_min) when the device reports its pressure range, and is
// left empty (full pressure) otherwise. Coordinates beyond kMaxGestureCoordinateMm are errors at
// the line of the frame that produced them.
#include <optional>
#include <string>
#include <vector>

#include "primitives/gesture.hpp"
#include "storage/touch_trace/evdev_trace.hpp"

namespace vimg {

struct TouchMapping {
  std::optional<double> panel_width_mm, panel_height_mm;  // --panel-mm WxH
  std::optional<double> units_per_mm;                     // --px-per-mm K
  std::optional<TouchAxis> x_range, y_range;              // replace the recording's ranges
};

struct TraceGestureResult {
  std::optional<Gesture> gesture;
  std::vector<std::string> errors;  // "FILE:LINE: error: problem"
  // Set when the mapping cannot be made at all (no ranges, or an empty one, for --panel-mm, no mapping given and no
  // resolution in the recording): what the user should pass. A usage error, not bad input.
  std::string usage_problem;
};

TraceGestureResult trace_to_gesture(const TouchTrace& trace, const TouchMapping& mapping, const std::string& file_name);

}  // namespace vimg
