#pragma once
// Gesture files (spec section 3): recorded finger paths, `time_s,finger,x_mm,y_mm,pressure,phase`,
// read into a Gesture (primitives/gesture.hpp): one stroke per finger's rows from its `down` to its
// `up` (or its last row). The limits (storage/limits.hpp, docs/limits.md) are enforced here.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "primitives/gesture.hpp"

namespace vimg {

struct GestureParseResult {
  std::optional<Gesture> gesture;   // set only when there is no error
  std::vector<std::string> errors;  // "FILE:LINE: error: problem"
  bool ok() const { return gesture.has_value(); }
};

// `file_name` is used in messages only.
GestureParseResult parse_gesture_csv(std::string_view text, const std::string& file_name);
// Reads through read_regular_file (kMaxCsvFileBytes) with load_file's wording ("FILE: error: " and
// read_file's reason), but not through storage/load_file.hpp itself: its problems are strings, not
// Diagnostics, and about ten readers of `errors` (the commands, vimg-player, the page's wasm, the
// editor's recorder) would change with them; left for a change of its own.
GestureParseResult load_gesture_file(const std::filesystem::path& path);

// One row of a gesture file, as a recorder takes it from a touch panel.
enum class GesturePhase { down, move, up };
struct GestureRow {
  double time_s = 0.0;
  int finger = 0;
  double x_mm = 0.0;
  double y_mm = 0.0;
  std::optional<double> pressure;  // absent: the device does not report pressure (an empty cell)
  GesturePhase phase = GesturePhase::move;
};

// The CSV text of rows in the order given: `# comment` first when there is one, the header, then
// one line per row, numbers in their shortest round-trip form.
std::string write_gesture_rows(const std::vector<GestureRow>& rows, std::string_view comment = {});

// The CSV text of a gesture (header, then rows in time order; the first row of a stroke is `down`,
// its last `up`).
std::string write_gesture_csv(const Gesture& gesture);

}  // namespace vimg
