#pragma once
// A touch recording (evemu-record or Android `getevent -lt` text, evdev_line.hpp) read into the
// contacts of each finger, in the digitizer's own units:
//   - multi-touch protocol B: one contact per tracking id, the finger is its slot;
//   - protocol A (SYN_MT_REPORT): contacts follow their ABS_MT_TRACKING_ID when the device sends
//     one, otherwise the nearest contact of the previous frame; a new contact takes the lowest free
//     finger number;
//   - single touch (BTN_TOUCH with ABS_X/ABS_Y): one finger.
// Each SYN_REPORT frame gives each finger whose contact changed one sample: `down` when it
// starts, `move`, `up` when it ends (at its last position). Times are relative to the first event.
// A recording of several devices (getevent) is read for the first device that reports touches.
// A `;`-separated touch log (touch_log.hpp) is read as such.
// Limits: kMaxTouchTraceFileBytes, kMaxGestureRows samples, kMaxTouchTraceFinger fingers at once.
// Messages: at most kMaxDiagnosticsPerFile (DiagnosticList). Reading stops at an event after an
// error; the bad lines before that event beyond the limit are counted on the summary line.
// A file that is not text (binary data: a NUL, another control character, bytes that are not UTF-8;
// storage/text_bytes.hpp) is refused with one message once 3 of its lines are such, "FILE: error:
// this is not a text touch recording (binary data at byte N)", N counted from 0 as hexdump does;
// fewer such lines are each one error, "the line is not text (binary data at byte N)", never shown.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/diagnostic.hpp"

namespace vimg {

struct TouchAxis {
  double min = 0.0;
  double max = 0.0;
  double units_per_mm = 0.0;  // the device's resolution, 0 when unknown
  int line = 0;               // the line that gave the range; 0 when the recording gives none
  bool known() const { return max > min; }
};

// Why `axis` cannot map positions onto a panel ("" when it can), to follow the file's name: "has
// none (an evemu-record header or getevent -lp lines give them)" when the recording gives no range,
// "gives an empty x range (min 5 = max 5, line 12)" or "gives a reversed x range (min 9 > max 5,
// line 12)"; `name` is the axis ("x").
std::string touch_axis_problem(const TouchAxis& axis, const std::string& name);

// The message for a recording whose events span more than a gesture may last (kMaxGestureDurationS):
// "the recording is longer than 600 s (limit 600)". Both readers (evemu/getevent, touch log) use it,
// so that every recording they accept makes a gesture the gesture reader takes back.
std::string touch_trace_too_long_problem();

struct TouchSample {
  enum class Phase { down, move, up };
  double time_s = 0.0;  // since the first event of the recording
  double x = 0.0;       // digitizer units
  double y = 0.0;
  std::optional<double> pressure;  // digitizer units; unset when the device reports none
  Phase phase = Phase::move;
  int line = 0;  // the line of the frame's SYN_REPORT, for messages
};

struct TouchContact {
  int finger = 0;
  std::vector<TouchSample> samples;  // the first is the down, the last the up
};

struct TouchTrace {
  enum class Protocol { a, b, single };
  Protocol protocol = Protocol::b;
  TouchAxis x, y, pressure;  // from the recording's header, when it has one
  std::vector<TouchContact> contacts;  // in the order they start
  double duration_s = 0.0;             // last event minus first event
  int last_line = 0;
};

struct TouchTraceParseResult {
  std::optional<TouchTrace> trace;  // set only when there is no error
  std::vector<Diagnostic> diagnostics;
};

TouchTraceParseResult parse_touch_trace(std::string_view text, const std::string& file_name);
TouchTraceParseResult load_touch_trace(const std::filesystem::path& path);

}  // namespace vimg
