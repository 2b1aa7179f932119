#include <gtest/gtest.h>

#include <cctype>
#include <random>

#include "storage/gesture_csv.hpp"
#include "storage/limits.hpp"

namespace vimg {
namespace {

constexpr const char* kHeader = "time_s,finger,x_mm,y_mm,pressure,phase\n";

GestureParseResult parse(const std::string& body) { return parse_gesture_csv(kHeader + body, "g.csv"); }

TEST(GestureParse, SpecExampleGivesOneStroke) {
  const auto r = parse_gesture_csv(
      "# time_s,finger,x_mm,y_mm,pressure,phase\n"
      "time_s,finger,x_mm,y_mm,pressure,phase\n"
      "0.000,0,5.0,20.0,1.0,down\n"
      "0.010,0,6.0,20.0,1.0,move\n"
      "0.400,0,45.0,20.0,,up\n",
      "g.csv");
  ASSERT_TRUE(r.ok()) << r.errors.front();
  ASSERT_EQ(r.gesture->strokes.size(), 1u);
  const auto& pts = r.gesture->strokes[0].points;
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_DOUBLE_EQ(pts[2].x_mm, 45.0);
  EXPECT_DOUBLE_EQ(pts[2].pressure, 1.0);  // empty pressure means full pressure
  EXPECT_DOUBLE_EQ(r.gesture->end_time_s(), 0.4);
}

TEST(GestureParse, HeaderIsRequired) {
  const auto r = parse_gesture_csv("0,0,1,1,1,down\n", "g.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors.front().rfind("g.csv:1: error:", 0), 0u) << r.errors.front();
}

TEST(GestureParse, EmptyFileIsAnError) {
  const auto r = parse_gesture_csv("# only a comment\n", "g.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors.front().find("header"), std::string::npos);
}

TEST(GestureParse, ErrorsNameFileLineAndProblem) {
  struct Case {
    std::string body;
    int line;
    std::string words;
  };
  const Case cases[] = {
      {"0,0,1,1,1,touch\n", 2, "phase"},
      {"0,0,1,1,1.5,down\n", 2, "pressure"},
      {"0,0,1,1,-0.1,down\n", 2, "pressure"},
      {"0,-1,1,1,1,down\n", 2, "finger"},
      {"0,x,1,1,1,down\n", 2, "finger"},
      {"0,0,nan,1,1,down\n", 2, "x_mm"},
      {"0,0,1,inf,1,down\n", 2, "y_mm"},
      {"0,0,0x10,1,1,down\n", 2, "x_mm"},
      {"abc,0,1,1,1,down\n", 2, "time_s"},
      {"0,0,1,1,1\n", 2, "6 fields"},
      {"0,0,1,1,1,down\n0.5,0,2,1,1,move\n0.4,0,3,1,1,move\n", 4, "before the previous row"},
      {"0,0,1,1,1,move\n", 2, "not down"},
      {"0,0,1,1,1,down\n0.1,0,1,1,1,down\n", 3, "already down"},
      {"0,0,1,1,1,up\n", 2, "not down"},
  };
  for (const auto& c : cases) {
    const auto r = parse(c.body);
    ASSERT_FALSE(r.ok()) << c.body;
    const std::string prefix = "g.csv:" + std::to_string(c.line) + ": error: ";
    EXPECT_EQ(r.errors.front().rfind(prefix, 0), 0u) << r.errors.front();
    EXPECT_NE(r.errors.front().find(c.words), std::string::npos) << r.errors.front();
  }
}

TEST(GestureParse, TimeMayDecreaseAcrossFingersButNotWithinOne) {
  const auto r = parse("0.5,0,1,1,1,down\n0.1,1,1,1,1,down\n0.6,0,2,1,1,up\n0.7,1,2,1,1,up\n");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.gesture->strokes.size(), 2u);
  EXPECT_EQ(r.gesture->strokes[0].finger, 1);  // ordered by start time
  EXPECT_DOUBLE_EQ(r.gesture->start_time_s(), 0.1);
}

TEST(GestureParse, FingerStillDownLiftsAtItsLastRow) {
  const auto r = parse("0,0,1,1,1,down\n0.2,0,5,1,1,move\n0.1,1,1,1,1,down\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.gesture->strokes.size(), 2u);
  EXPECT_DOUBLE_EQ(r.gesture->strokes[0].points.back().time_s, 0.2);
  EXPECT_DOUBLE_EQ(r.gesture->end_time_s(), 0.2);
}

TEST(GestureParse, AFingerCanTouchAgainAfterLifting) {
  const auto r = parse("0,0,1,1,1,down\n0.1,0,2,1,1,up\n0.2,0,3,1,0.5,down\n0.3,0,4,1,0.5,up\n");
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.gesture->strokes.size(), 2u);
  EXPECT_DOUBLE_EQ(r.gesture->strokes[1].points[0].pressure, 0.5);
}

TEST(GestureParse, CrlfAndSpacesAreAccepted) {
  const auto r = parse_gesture_csv("time_s,finger,x_mm,y_mm,pressure,phase\r\n 0 , 0 , 1 , 1 , , down\r\n", "g.csv");
  ASSERT_TRUE(r.ok()) << r.errors.front();
}

TEST(GestureParse, WriteThenParseRoundTrips) {
  const auto r = parse("0,0,1,1,1,down\n0.1,1,3,3,0.25,down\n0.2,0,2,1,1,move\n0.3,0,2.5,1,1,up\n0.4,1,4,4,1,up\n");
  ASSERT_TRUE(r.ok());
  const auto again = parse_gesture_csv(write_gesture_csv(*r.gesture), "w.csv");
  ASSERT_TRUE(again.ok());
  ASSERT_EQ(again.gesture->strokes.size(), r.gesture->strokes.size());
  for (std::size_t i = 0; i < r.gesture->strokes.size(); ++i) {
    const auto& a = r.gesture->strokes[i];
    const auto& b = again.gesture->strokes[i];
    EXPECT_EQ(a.finger, b.finger);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t k = 0; k < a.points.size(); ++k) {
      EXPECT_EQ(a.points[k].time_s, b.points[k].time_s);
      EXPECT_EQ(a.points[k].x_mm, b.points[k].x_mm);
      EXPECT_EQ(a.points[k].pressure, b.points[k].pressure);
    }
  }
}

TEST(GestureParse, MutatedFilesGiveLocatedErrorsOrValidGestures) {
  const std::string valid = std::string(kHeader) +
                            "0.000,0,5.0,20.0,1.0,down\n0.010,0,6.0,20.0,0.5,move\n0.005,1,1,1,,down\n"
                            "0.400,0,45.0,20.0,,up\n0.5,1,2,2,1,up\n";
  // "g.csv:LINE: error: PROBLEM" with LINE a number and PROBLEM printable text.
  auto located = [](const std::string& e) {
    if (e.rfind("g.csv:", 0) != 0) return false;
    std::size_t i = 6;
    while (i < e.size() && std::isdigit(static_cast<unsigned char>(e[i]))) ++i;
    if (i == 6 || e.compare(i, 9, ": error: ") != 0 || i + 9 >= e.size()) return false;
    for (char c : e) {
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) return false;
    }
    return true;
  };
  std::mt19937 rng(1234);
  const std::string alphabet = "0123456789.,-+eE \n\r#abcdownupmve\t";
  for (int round = 0; round < 3000; ++round) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % (text.size() + 1);
      switch (rng() % 3) {
        case 0: text.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
        case 1: if (at < text.size()) text.erase(at, 1); break;
        default: if (at < text.size()) text[at] = static_cast<char>(rng() % 256); break;
      }
    }
    const auto r = parse_gesture_csv(text, "g.csv");
    if (r.ok()) {
      for (const auto& s : r.gesture->strokes) {
        ASSERT_FALSE(s.points.empty());
        for (std::size_t k = 0; k < s.points.size(); ++k) {
          ASSERT_TRUE(s.points[k].pressure >= 0.0 && s.points[k].pressure <= 1.0);
          if (k > 0) {
            ASSERT_GE(s.points[k].time_s, s.points[k - 1].time_s);
          }
        }
      }
    } else {
      ASSERT_FALSE(r.errors.empty());
      for (const auto& e : r.errors) ASSERT_TRUE(located(e)) << e;
    }
  }
}

TEST(GestureParse, HugeTimesCoordinatesAndDurationsAreRefusedWithTheirLimit) {
  const std::string header = "time_s,finger,x_mm,y_mm,pressure,phase\n";
  const auto first_error = [&](const std::string& rows) {
    const GestureParseResult r = parse_gesture_csv(header + rows, "g.csv");
    EXPECT_FALSE(r.ok()) << rows;
    return r.errors.empty() ? std::string() : r.errors.front();
  };
  EXPECT_EQ(first_error("1e6,0,1,1,,down\n"), "g.csv:2: error: time_s '1e6' is beyond 86400 s (limit 86400)");
  EXPECT_EQ(first_error("0,0,1,1,,down\n1e300,0,2,2,,up\n"), "g.csv:3: error: time_s '1e300' is beyond 86400 s (limit 86400)");
  EXPECT_EQ(first_error("0,0,1e9,1,,down\n"), "g.csv:2: error: x_mm '1e9' is beyond 10000 mm (limit 10000)");
  EXPECT_EQ(first_error("0,0,1,-2e4,,down\n"), "g.csv:2: error: y_mm '-2e4' is beyond 10000 mm (limit 10000)");
  // A span over ten minutes, also across fingers whose times decrease.
  EXPECT_EQ(first_error("0,0,1,1,,down\n700,0,2,2,,up\n"), "g.csv:3: error: the gesture lasts more than 600 s (limit 600)");
  EXPECT_EQ(first_error("800,0,1,1,,down\n100,1,2,2,,down\n"), "g.csv:3: error: the gesture lasts more than 600 s (limit 600)");
  // Within the limits it is fine.
  EXPECT_TRUE(parse_gesture_csv(header + "0,0,1,1,,down\n600,0,2,2,,up\n", "g.csv").ok());
}

TEST(GestureParse, MoreRowsThanTheLimitStopAtTheFirstRowOver) {
  std::string text = "time_s,finger,x_mm,y_mm,pressure,phase\n0,0,1,1,,down\n";
  text.reserve(30 * kMaxGestureRows);
  for (std::size_t i = 1; i < kMaxGestureRows; ++i) text += "1,0,1,1,,move\n";
  EXPECT_TRUE(parse_gesture_csv(text, "g.csv").ok());
  text += "1,0,1,1,,move\n";
  const GestureParseResult r = parse_gesture_csv(text, "g.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors.front(), "g.csv:" + std::to_string(kMaxGestureRows + 2) + ": error: more than " +
                                  std::to_string(kMaxGestureRows) + " rows (limit " + std::to_string(kMaxGestureRows) + ")");
}

TEST(GestureParse, DevicesAndFifosAreRefusedWithoutReading) {
  const GestureParseResult zero = load_gesture_file("/dev/zero");
  ASSERT_FALSE(zero.ok());
  EXPECT_EQ(zero.errors.front(), "/dev/zero: error: is not a regular file (a character device)");
}

TEST(GestureParse, MissingFileIsAnErrorNamingIt) {
  const auto r = load_gesture_file("/nonexistent/g.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors.front().find("/nonexistent/g.csv"), std::string::npos);
}

}  // namespace
}  // namespace vimg
