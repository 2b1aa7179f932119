#pragma once
// A touch log of one finger, one event a line, `;`-separated, no header:
//   epoch_ms;time_ms;x;y;size;action      action: 0 down, 1 up, 2 move
// (the format of the Henze et al. latency-prediction traces, tests/data/touch-latency-henze2017).
// It is read into a TouchTrace (evdev_trace.hpp) of single-touch contacts in the log's own units:
// each down starts a contact, moves follow it, an up ends it. Times are time_ms / 1000, relative
// to the first line; the x and y units are the log's (pixels: give --px-per-mm). A move or up
// without a down, or a down before the previous contact's up, is an error at its line; time_ms may
// repeat but never decrease. Limits: kMaxTouchTraceFileBytes, kMaxGestureRows events, and
// kMaxGestureDurationS from the first line's time_ms (touch_trace_too_long_problem()).
// parse_touch_trace() and load_touch_trace() read this format when looks_like_touch_log() says so.
#include <string>
#include <string_view>

#include "storage/touch_trace/evdev_trace.hpp"

namespace vimg {

// True when the text's first non-empty line has the shape above (six ';'-separated fields).
bool looks_like_touch_log(std::string_view text);

TouchTraceParseResult parse_touch_log(std::string_view text, const std::string& file_name);

}  // namespace vimg
