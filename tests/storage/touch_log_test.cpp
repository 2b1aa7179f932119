// The `;`-separated touch log (storage/touch_trace/touch_log.hpp), read through parse_touch_trace as
// `vimg gesture import` reads it: strokes from down to up, and every bad line named with its number.
#include <gtest/gtest.h>

#include <string>

#include "storage/touch_trace/evdev_trace.hpp"
#include "storage/limits.hpp"
#include "storage/touch_trace/touch_log.hpp"

namespace vimg {
namespace {

std::string first_error(const std::string& text) {
  const TouchTraceParseResult r = parse_touch_trace(text, "log.txt");
  EXPECT_FALSE(r.trace.has_value());
  for (const Diagnostic& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) return d.to_string();
  }
  return {};
}

TEST(TouchLog, StrokesRunFromDownToUpInTheLogsUnitsAndSeconds) {
  const TouchTraceParseResult r = parse_touch_trace(
      "100;1000;10;20;0.4;0\n117;1017;11;21;0.4;2\n117;1017;12;22;0.4;2\n150;1050;13;23;0.4;1\n"
      "300;1200;50;60;0.3;0\n320;1216;51;61;0.3;1\n",
      "log.txt");
  ASSERT_TRUE(r.trace.has_value());
  ASSERT_EQ(r.trace->contacts.size(), 2u);
  const TouchContact& a = r.trace->contacts[0];
  ASSERT_EQ(a.samples.size(), 4u);
  EXPECT_EQ(a.samples.front().phase, TouchSample::Phase::down);
  EXPECT_EQ(a.samples.back().phase, TouchSample::Phase::up);
  EXPECT_DOUBLE_EQ(a.samples[1].time_s, 0.017);
  EXPECT_DOUBLE_EQ(a.samples[2].x, 12.0);
  EXPECT_DOUBLE_EQ(r.trace->contacts[1].samples[0].time_s, 0.2);
  EXPECT_TRUE(looks_like_touch_log("1;2;3;4;5;0\n"));
  EXPECT_FALSE(looks_like_touch_log("E: 0.000001 0003 0035 1234\n"));
}

TEST(TouchLog, BadLinesAreNamedWithTheirNumbers) {
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;3;3;4;5;7\n"),
            "log.txt:2: error: action must be 0 (down), 1 (up) or 2 (move), got '7'");
  EXPECT_EQ(first_error("1;2;3;4;5;2\n"), "log.txt:1: error: a move without a down");
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;9;3;4;5;2\n1;5;3;4;5;2\n"),
            "log.txt:3: error: time_ms goes back from 5 to below the previous line's");
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;3;x;4;5;2\n"), "log.txt:2: error: x is not a finite number: 'x'");
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;3;3;4;5\n"),
            "log.txt:2: error: expected 6 fields separated by ';' (epoch_ms;time_ms;x;y;size;action), got '1;3;3;4;5'");
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;3;3;4;5;0\n"), "log.txt:2: error: a down before the previous touch's up");
}

// A log is held to the gesture's duration, as an evemu recording is: what it reads, the gesture
// reader (storage/gesture_csv.hpp) takes back (found by touch_trace_fuzz).
TEST(TouchLog, ALogLongerThanAGestureMayLastIsRefusedAtTheLineThatShowsIt) {
  const int limit_ms = static_cast<int>(kMaxGestureDurationS * 1000.0);
  const std::string at_limit = "1;2;3;4;5;0\n1;" + std::to_string(2 + limit_ms) + ";4;5;5;1\n";
  const TouchTraceParseResult r = parse_touch_trace(at_limit, "log.txt");
  ASSERT_TRUE(r.trace.has_value());
  EXPECT_DOUBLE_EQ(r.trace->duration_s, kMaxGestureDurationS);
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;5;4;5;5;2\n1;" + std::to_string(3 + limit_ms) + ";4;5;5;1\n"),
            "log.txt:3: error: the recording is longer than 600 s (limit 600)");
  EXPECT_EQ(first_error("1;2;3;4;5;0\n1;1e300;4;5;5;1\n"), "log.txt:2: error: the recording is longer than 600 s (limit 600)");
}

// A log of exactly kMaxGestureRows events makes a gesture; when it ends on a lone down, that
// touch's up would be one row more, and is refused rather than making a gesture nobody can read.
TEST(TouchLog, ALogAtTheRowLimitMakesAGestureAndALoneDownBeyondItIsRefused) {
  // One touch of kMaxGestureRows events: a down, moves, an up.
  std::string moves;
  for (std::size_t i = 0; i + 3 < kMaxGestureRows; ++i) moves += "1;10;3;4;5;2\n";
  const TouchTraceParseResult r = parse_touch_trace("1;10;3;4;5;0\n" + moves + "1;10;3;4;5;2\n1;10;3;4;5;1\n", "log.txt");
  ASSERT_TRUE(r.trace.has_value());
  EXPECT_EQ(r.trace->contacts.at(0).samples.size(), kMaxGestureRows);
  // The same count, with a touch one row shorter followed by a lone down as the last event.
  const std::string line = std::to_string(kMaxGestureRows);
  EXPECT_EQ(first_error("1;10;3;4;5;0\n" + moves + "1;10;3;4;5;1\n1;10;3;4;5;0\n"),
            "log.txt:" + line + ": error: the log ends during a touch, and its up would be gesture row " +
                std::to_string(kMaxGestureRows + 1) + " (limit " + line + " gesture rows)");
}

TEST(TouchLog, ALogCutDuringATouchLiftsItAtItsLastEventWithAWarning) {
  const TouchTraceParseResult r = parse_touch_trace("1;2;3;4;5;0\n1;19;4;5;5;2\n", "log.txt");
  ASSERT_TRUE(r.trace.has_value());
  ASSERT_EQ(r.trace->contacts[0].samples.size(), 2u);
  EXPECT_EQ(r.trace->contacts[0].samples.back().phase, TouchSample::Phase::up);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.back().severity, Diagnostic::Severity::warning);
}

}  // namespace
}  // namespace vimg
