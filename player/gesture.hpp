#pragma once
// Gesture files (spec section 3): recorded finger paths, `time_s,finger,x_mm,y_mm,pressure,phase`.
// A gesture is kept as strokes: one finger's rows from its `down` to its `up` (or its last row).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vimg {

struct GesturePoint {
  double time_s = 0.0;
  double x_mm = 0.0;
  double y_mm = 0.0;
  double pressure = 1.0;  // [0, 1]; 1 when the file leaves it empty
};

struct GestureStroke {
  int finger = 0;
  std::vector<GesturePoint> points;  // time never decreasing; first is the down, last the lift
};

struct Gesture {
  std::vector<GestureStroke> strokes;  // ordered by start time
  double start_time_s() const;
  double end_time_s() const;
};

struct GestureParseResult {
  std::optional<Gesture> gesture;   // set only when there is no error
  std::vector<std::string> errors;  // "FILE:LINE: error: problem"
  bool ok() const { return gesture.has_value(); }
};

inline constexpr int kMaxGestureFinger = 63;

// `file_name` is used in messages only.
GestureParseResult parse_gesture_csv(std::string_view text, const std::string& file_name);
GestureParseResult load_gesture_file(const std::filesystem::path& path);

// The CSV text of a gesture (header, then rows in time order; the last row of a stroke is `up`).
std::string write_gesture_csv(const Gesture& gesture);

}  // namespace vimg
