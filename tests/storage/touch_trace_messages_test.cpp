// What a touch recording's reader says (storage/touch_trace/): an empty axis range is called empty,
// not missing; past kMaxDiagnosticsPerFile messages, the rest are counted on one line
// (docs/limits.md, "Messages").
#include <gtest/gtest.h>

#include <string>

#include "storage/limits.hpp"
#include "storage/touch_trace/evdev_trace.hpp"

namespace vimg {
namespace {

// One finger down at (1, 1) and up.
const std::string kTouch =
    "E: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\nE: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\n"
    "E: 0.1 0003 0039 -1\nE: 0.1 0000 0000 0\n";

TEST(TouchTraceMessages, AnEmptyAxisRangeIsCalledEmptyAtItsLine) {
  const TouchTraceParseResult r = parse_touch_trace("A: 35 7 7 0 0 0\nA: 36 0 479 0 0 0\n" + kTouch, "t.evemu");
  ASSERT_TRUE(r.trace);
  EXPECT_FALSE(r.trace->x.known());
  EXPECT_EQ(touch_axis_problem(r.trace->x, "x"), "gives an empty x range (min 7 = max 7, line 1)");
  EXPECT_EQ(touch_axis_problem(r.trace->y, "y"), "");
}

TEST(TouchTraceMessages, AnEmptyRangeFromEvemuCommentsAndAReversedOne) {
  const std::string header =
      "# Event code 53 (ABS_MT_POSITION_X)\n#       Min    0\n#       Max    0\n"
      "# Event code 54 (ABS_MT_POSITION_Y)\n#       Min  900\n#       Max  100\n";
  const TouchTraceParseResult r = parse_touch_trace(header + kTouch, "t.evemu");
  ASSERT_TRUE(r.trace);
  EXPECT_EQ(touch_axis_problem(r.trace->x, "x"), "gives an empty x range (min 0 = max 0, line 3)");
  EXPECT_EQ(touch_axis_problem(r.trace->y, "y"), "gives a reversed y range (min 900 > max 100, line 6)");
}

TEST(TouchTraceMessages, NoRangeAtAllIsStillNone) {
  const TouchTraceParseResult r = parse_touch_trace(kTouch, "t.evemu");
  ASSERT_TRUE(r.trace);
  EXPECT_EQ(touch_axis_problem(r.trace->x, "x"), "has none (an evemu-record header or getevent -lp lines give them)");
}

// 60 bad lines: the first 50 at their lines, then "10 more diagnostics not shown".
TEST(TouchTraceMessages, PastTheLimitTheRestAreCounted) {
  std::string text;
  for (int i = 0; i < 60; ++i) text += "nonsense " + std::to_string(i) + "\n";
  const TouchTraceParseResult r = parse_touch_trace(text, "t.evemu");
  EXPECT_FALSE(r.trace);
  ASSERT_EQ(r.diagnostics.size(), kMaxDiagnosticsPerFile + 1);
  EXPECT_EQ(r.diagnostics[49].line, 50);
  EXPECT_EQ(r.diagnostics.back().to_string(), "t.evemu: error: 10 more diagnostics not shown: 10 errors (limit 50 per file)");
}

// Reading stops at the first event after an error: the bad lines before it are all counted, those
// after it are not read.
TEST(TouchTraceMessages, TheCountEndsWhereReadingStops) {
  std::string text;
  for (int i = 0; i < 53; ++i) text += "nonsense\n";
  text += kTouch;
  for (int i = 0; i < 5; ++i) text += "nonsense\n";
  const TouchTraceParseResult r = parse_touch_trace(text, "t.evemu");
  ASSERT_EQ(r.diagnostics.size(), kMaxDiagnosticsPerFile + 1);
  EXPECT_EQ(r.diagnostics.back().to_string(), "t.evemu: error: 3 more diagnostics not shown: 3 errors (limit 50 per file)");
  const TouchTraceParseResult exactly = parse_touch_trace(text.substr(0, 50 * 9) + kTouch, "t.evemu");
  ASSERT_EQ(exactly.diagnostics.size(), kMaxDiagnosticsPerFile);  // no summary when nothing is left out
  EXPECT_EQ(exactly.diagnostics.back().line, 50);
}

}  // namespace
}  // namespace vimg
