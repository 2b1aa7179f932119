// Touch recordings (storage/touch_trace/): real evemu recordings and hand-written protocol A and
// getevent files (tests/data/evdev/README.md) become the contacts of each finger; bad input gives
// FILE:LINE messages.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "storage/touch_trace/evdev_trace.hpp"

namespace vimg {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(VIMG_TEST_DATA_DIR) / "evdev";

std::string first_message(const TouchTraceParseResult& r) {
  for (const auto& d : r.diagnostics) {
    if (d.severity == Diagnostic::Severity::error) return d.to_string();
  }
  return {};
}

using Phase = TouchSample::Phase;

// The real two-finger recording of whot/evemu-devices: two contacts, on slots 0 and 1, from the
// first event to the last (0.824235 s), at the positions the events give.
TEST(TouchTrace, AtmelTwoFingerRecordingGivesTwoFingersOverItsWholeDuration) {
  const TouchTraceParseResult r = load_touch_trace(kData / "atmel-maxtouch.2-fingers-touch-release.evemu");
  ASSERT_TRUE(r.trace) << first_message(r);
  const TouchTrace& t = *r.trace;
  EXPECT_EQ(t.protocol, TouchTrace::Protocol::b);
  EXPECT_DOUBLE_EQ(t.duration_s, 0.824235);
  EXPECT_EQ(t.x.min, 0.0);
  EXPECT_EQ(t.x.max, 799.0);
  EXPECT_EQ(t.y.max, 479.0);
  ASSERT_EQ(t.contacts.size(), 2u);
  const TouchContact& a = t.contacts[0];
  const TouchContact& b = t.contacts[1];
  EXPECT_EQ(a.finger, 0);
  EXPECT_EQ(b.finger, 1);
  EXPECT_EQ(a.samples.front().phase, Phase::down);
  EXPECT_DOUBLE_EQ(a.samples.front().time_s, 0.0);
  EXPECT_EQ(a.samples.front().x, 539.0);
  EXPECT_EQ(a.samples.front().y, 167.0);
  EXPECT_EQ(a.samples.back().phase, Phase::up);
  EXPECT_DOUBLE_EQ(a.samples.back().time_s, 0.824235);
  EXPECT_EQ(a.samples.back().x, 538.0);
  EXPECT_EQ(a.samples.back().y, 176.0);
  EXPECT_DOUBLE_EQ(b.samples.front().time_s, 0.054564);
  EXPECT_EQ(b.samples.front().x, 222.0);
  EXPECT_EQ(b.samples.front().y, 306.0);
  EXPECT_DOUBLE_EQ(b.samples.back().time_s, 0.810269);
  EXPECT_EQ(b.samples.back().x, 224.0);
  EXPECT_EQ(b.samples.back().y, 312.0);
  for (const auto& c : t.contacts) {
    for (std::size_t i = 1; i + 1 < c.samples.size(); ++i) EXPECT_EQ(c.samples[i].phase, Phase::move);
    EXPECT_FALSE(c.samples.front().pressure.has_value());
  }
}

TEST(TouchTrace, EventsOnlyRecordingHasNoRangesAndTwoFingers) {
  const TouchTraceParseResult r = load_touch_trace(kData / "wacom-isdv4-e6.2fg-tap.events");
  ASSERT_TRUE(r.trace) << first_message(r);
  EXPECT_FALSE(r.trace->x.known());
  ASSERT_EQ(r.trace->contacts.size(), 2u);
  EXPECT_EQ(r.trace->contacts[1].samples.front().x, 1287.0);
  EXPECT_DOUBLE_EQ(r.trace->duration_s, 0.032008);
}

// Protocol A without tracking ids: contacts follow the nearest contact of the previous frame,
// whatever order the device lists them in.
TEST(TouchTrace, ProtocolAFollowsEachContactByNearness) {
  const TouchTraceParseResult r = load_touch_trace(kData / "protocol-a.two-fingers.evemu");
  ASSERT_TRUE(r.trace) << first_message(r);
  EXPECT_EQ(r.trace->protocol, TouchTrace::Protocol::a);
  ASSERT_EQ(r.trace->contacts.size(), 2u);
  const auto xs = [](const TouchContact& c) {
    std::vector<double> v;
    for (const auto& s : c.samples) v.push_back(s.x);
    return v;
  };
  EXPECT_EQ(xs(r.trace->contacts[0]), (std::vector<double>{100, 150, 250, 250}));
  EXPECT_EQ(xs(r.trace->contacts[1]), (std::vector<double>{800, 700, 600, 600}));
  EXPECT_DOUBLE_EQ(r.trace->contacts[0].samples.back().time_s, 0.3);
  EXPECT_DOUBLE_EQ(r.trace->contacts[1].samples.back().time_s, 0.4);
  EXPECT_EQ(r.trace->contacts[1].finger, 1);
  EXPECT_EQ(*r.trace->contacts[1].samples.front().pressure, 51.0);
  EXPECT_EQ(r.trace->pressure.max, 255.0);
}

TEST(TouchTrace, GeteventTextWithAxisLinesAndAnotherDevice) {
  const TouchTraceParseResult r = load_touch_trace(kData / "getevent.two-fingers.txt");
  ASSERT_TRUE(r.trace) << first_message(r);
  const TouchTrace& t = *r.trace;
  EXPECT_EQ(t.x.max, 1199.0);
  EXPECT_EQ(t.y.max, 2399.0);
  ASSERT_EQ(t.contacts.size(), 2u);
  EXPECT_DOUBLE_EQ(t.contacts[0].samples.front().time_s, 0.0);  // the key on event0 is not the touch screen
  EXPECT_EQ(t.contacts[0].samples.front().x, 300.0);
  EXPECT_EQ(t.contacts[0].samples.back().y, 1200.0);
  EXPECT_EQ(t.contacts[1].samples.back().y, 1000.0);
  EXPECT_DOUBLE_EQ(t.contacts[1].samples.back().time_s, 0.45);
  EXPECT_DOUBLE_EQ(t.duration_s, 0.5);
}

TEST(TouchTrace, SingleTouchAndANewTrackingIdInTheSameSlot) {
  const TouchTraceParseResult single = parse_touch_trace(
      "E: 1.0 0003 0000 10\nE: 1.0 0003 0001 20\nE: 1.0 0001 014a 1\nE: 1.0 0000 0000 0\n"
      "E: 1.5 0003 0000 30\nE: 1.5 0000 0000 0\nE: 2.0 0001 014a 0\nE: 2.0 0000 0000 0\n",
      "s.evemu");
  ASSERT_TRUE(single.trace) << first_message(single);
  EXPECT_EQ(single.trace->protocol, TouchTrace::Protocol::single);
  ASSERT_EQ(single.trace->contacts.size(), 1u);
  EXPECT_EQ(single.trace->contacts[0].samples.size(), 3u);
  EXPECT_EQ(single.trace->contacts[0].samples[1].x, 30.0);
  const TouchTraceParseResult swap = parse_touch_trace(
      "E: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\nE: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\n"
      "E: 0.1 0003 0039 6\nE: 0.1 0003 0035 9\nE: 0.1 0000 0000 0\nE: 0.2 0003 0039 -1\nE: 0.2 0000 0000 0\n",
      "b.evemu");
  ASSERT_TRUE(swap.trace) << first_message(swap);
  ASSERT_EQ(swap.trace->contacts.size(), 2u);
  EXPECT_EQ(swap.trace->contacts[0].samples.back().phase, Phase::up);
  EXPECT_DOUBLE_EQ(swap.trace->contacts[0].samples.back().time_s, 0.1);
  EXPECT_EQ(swap.trace->contacts[1].samples.front().x, 9.0);
}

// Found by the fuzzer: a single-touch contact followed by protocol-A contacts gave finger 0 twice.
TEST(TouchTrace, MultiTouchAfterSingleTouchEndsTheSingleContactFirst) {
  const TouchTraceParseResult r = parse_touch_trace(
      "E: 0.0 0001 014a 1\nE: 0.0 0003 0000 5\nE: 0.0 0003 0001 5\nE: 0.0 0000 0000 0\n"
      "E: 0.1 0003 0035 7\nE: 0.1 0003 0036 7\nE: 0.1 0000 0002 0\nE: 0.1 0000 0000 0\nE: 0.2 0000 0002 0\nE: 0.2 0000 0000 0\n",
      "m.evemu");
  ASSERT_TRUE(r.trace) << first_message(r);
  ASSERT_EQ(r.trace->contacts.size(), 2u);
  EXPECT_EQ(r.trace->contacts[0].finger, 0);
  EXPECT_EQ(r.trace->contacts[1].finger, 0);
  EXPECT_DOUBLE_EQ(r.trace->contacts[0].samples.back().time_s, 0.1);
  EXPECT_EQ(r.trace->contacts[0].samples.back().phase, Phase::up);
  EXPECT_DOUBLE_EQ(r.trace->contacts[1].samples.front().time_s, 0.1);
}

TEST(TouchTrace, AFingerStillDownAtTheEndLiftsThereWithAWarning) {
  const TouchTraceParseResult r =
      parse_touch_trace("E: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\nE: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\nE: 0.3 0000 0000 0\n", "d.evemu");
  ASSERT_TRUE(r.trace) << first_message(r);
  EXPECT_EQ(r.trace->contacts[0].samples.back().phase, Phase::up);
  EXPECT_DOUBLE_EQ(r.trace->contacts[0].samples.back().time_s, 0.3);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].to_string(), "d.evemu:5: warning: finger 0 is still down at the end of the recording; it lifts there");
}

TEST(TouchTrace, BadInputNamesFileAndLine) {
  const std::string down = "E: 0.0 0003 0039 5\nE: 0.0 0003 0035 1\nE: 0.0 0003 0036 1\nE: 0.0 0000 0000 0\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"hello\n", "t:1: error: expected an evemu event"},
      {"E: 0.0 0003 0035\n", "t:1: error: an evemu event needs 4 fields"},
      {"E: x.0 0003 0035 1\n", "t:1: error: bad time 'x.0'"},
      {"E: 0.0 0003 0035 1.5\n", "t:1: error: bad value '1.5'"},
      {"[ 1.0] /dev/input/event1: EV_ABS ABS_MT_POSITION_X zz\n", "t:1: error: bad value 'zz'"},
      {down + "E: -1.0 0000 0000 0\n", "t:5: error: bad time"},
      {"E: 5.0 0003 0035 1\nE: 4.0 0000 0000 0\n", "t:2: error: time goes backwards"},
      {"E: 133048000000000.0 0003 0035 1\nE: 0.0 0000 0000 0\n", "t:2: error: time goes backwards"},  // found by the fuzzer
      {down + "E: 700.0 0000 0000 0\n", "t:5: error: the recording is longer than 600 s (limit 600)"},
      {"E: 0.0 0003 002f 64\n", "t:1: error: slot 64 is beyond"},
      {down + "E: 0.1 0003 0035 1\nE: 0.1 0000 0002 0\n", "t:6: error: the recording mixes multi-touch protocols A"},
      {"E: 0.0 0000 0000 0\n", "t:1: error: the recording has no touches"},
  };
  for (const auto& [text, expected] : cases) {
    const TouchTraceParseResult r = parse_touch_trace(text, "t");
    EXPECT_FALSE(r.trace);
    EXPECT_EQ(first_message(r).rfind(expected, 0), 0u) << "got: " << first_message(r) << "\nwanted: " << expected;
  }
}

// Property: random protocol-B recordings of up to 5 fingers come back as the contacts written.
TEST(TouchTrace, RandomProtocolBRecordingsRoundTrip) {
  std::mt19937 rng(4);
  for (int round = 0; round < 50; ++round) {
    struct Finger {
      int slot;
      int start, end;  // frame numbers
      std::vector<std::pair<int, int>> xy;
    };
    const int frames = 5 + static_cast<int>(rng() % 30);
    std::vector<Finger> fingers;
    const int n = 1 + static_cast<int>(rng() % 5);
    for (int f = 0; f < n; ++f) {
      Finger g{f, static_cast<int>(rng() % static_cast<unsigned>(frames - 2)), 0, {}};
      g.end = g.start + 1 + static_cast<int>(rng() % static_cast<unsigned>(frames - g.start - 1));
      for (int i = g.start; i <= g.end; ++i) g.xy.emplace_back(static_cast<int>(rng() % 4000), static_cast<int>(rng() % 4000));
      fingers.push_back(g);
    }
    std::string text;
    for (int frame = 0; frame <= frames; ++frame) {
      char time[32];
      std::snprintf(time, sizeof time, "E: %d.%06d ", 100 + frame / 100, (frame % 100) * 10000);
      for (const Finger& g : fingers) {
        if (frame < g.start || frame > g.end) continue;
        text += std::string(time) + "0003 002f " + std::to_string(g.slot) + "\n";
        if (frame == g.start) text += std::string(time) + "0003 0039 " + std::to_string(1000 + g.slot) + "\n";
        if (frame == g.end) {
          text += std::string(time) + "0003 0039 -1\n";
          continue;
        }
        const auto [x, y] = g.xy[static_cast<std::size_t>(frame - g.start)];
        text += std::string(time) + "0003 0035 " + std::to_string(x) + "\n" + time + "0003 0036 " + std::to_string(y) + "\n";
      }
      text += std::string(time) + "0000 0000 0\n";
    }
    const TouchTraceParseResult r = parse_touch_trace(text, "p");
    ASSERT_TRUE(r.trace) << first_message(r) << "\n" << text;
    ASSERT_EQ(r.trace->contacts.size(), fingers.size());
    for (const TouchContact& c : r.trace->contacts) {
      const Finger& g = fingers[static_cast<std::size_t>(c.finger)];
      ASSERT_EQ(c.samples.size(), static_cast<std::size_t>(g.end - g.start + 1));
      EXPECT_DOUBLE_EQ(c.samples.front().time_s, g.start * 0.01);
      EXPECT_DOUBLE_EQ(c.samples.back().time_s, g.end * 0.01);
      for (std::size_t i = 0; i + 1 < c.samples.size(); ++i) {
        EXPECT_EQ(c.samples[i].x, g.xy[i].first);
        EXPECT_EQ(c.samples[i].y, g.xy[i].second);
      }
    }
  }
}

}  // namespace
}  // namespace vimg
