// The standard exploration (study/exploration.hpp): passes at every speed across the whole canvas,
// one stroke per (speed, direction), the duration bounded on a large canvas.
#include "study/exploration.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vimg::study {
namespace {

TEST(Exploration, SixSerpentinesCoverTheCanvasAtThreeSpeeds) {
  const Exploration e = *standard_exploration(60.0, 110.0);
  ASSERT_EQ(e.gesture.strokes.size(), 6u);  // 3 speeds x (horizontal, vertical)
  EXPECT_DOUBLE_EQ(e.pass_spacing_mm, 10.0);
  double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
  for (const GestureStroke& s : e.gesture.strokes) {
    EXPECT_EQ(s.finger, 0);
    for (const GesturePoint& p : s.points) {
      min_x = std::min(min_x, p.x_mm);
      max_x = std::max(max_x, p.x_mm);
      min_y = std::min(min_y, p.y_mm);
      max_y = std::max(max_y, p.y_mm);
    }
  }
  EXPECT_NEAR(min_x, 0.0, 1e-9);
  EXPECT_NEAR(max_x, 60.0, 1e-9);
  EXPECT_NEAR(min_y, 0.0, 1e-9);
  EXPECT_NEAR(max_y, 110.0, 1e-9);
  // Strokes follow each other with the finger lifted in between.
  for (std::size_t i = 1; i < e.gesture.strokes.size(); ++i) {
    EXPECT_NEAR(e.gesture.strokes[i].points.front().time_s - e.gesture.strokes[i - 1].points.back().time_s, 0.1, 1e-9);
  }
  EXPECT_NEAR(e.gesture.start_time_s(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(e.duration_s, e.gesture.end_time_s());
  EXPECT_GT(e.duration_s, 40.0);
  EXPECT_LT(e.duration_s, 120.0);
}

TEST(Exploration, EachStrokeMovesAtItsSpeed) {
  const Exploration e = *standard_exploration(60.0, 110.0);
  const double speeds[] = {40.0, 40.0, 100.0, 100.0, 250.0, 250.0};
  for (std::size_t i = 0; i < e.gesture.strokes.size(); ++i) {
    const auto& pts = e.gesture.strokes[i].points;
    double length = 0.0;
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const double step = std::hypot(pts[k].x_mm - pts[k - 1].x_mm, pts[k].y_mm - pts[k - 1].y_mm);
      const double dt = pts[k].time_s - pts[k - 1].time_s;
      ASSERT_GE(dt, 0.0);
      if (dt > 1e-6) {
        EXPECT_NEAR(step / dt, speeds[i], 1e-6 * speeds[i]) << "stroke " << i << " event " << k;
      }
      length += step;
    }
    EXPECT_NEAR(length / (pts.back().time_s - pts.front().time_s), speeds[i], 1e-6 * speeds[i]);
  }
}

TEST(Exploration, TheSpeedsInterleaveSoThatTogetherTheyCrossEveryThirdOfTheSpacing) {
  const Exploration e = *standard_exploration(100.0, 100.0);
  // The first point of each horizontal stroke is on its first row: 10 * (k + 0.5) / 3.
  EXPECT_NEAR(e.gesture.strokes[0].points.front().y_mm, 10.0 * 0.5 / 3.0, 1e-9);
  EXPECT_NEAR(e.gesture.strokes[2].points.front().y_mm, 10.0 * 1.5 / 3.0, 1e-9);
  EXPECT_NEAR(e.gesture.strokes[4].points.front().y_mm, 10.0 * 2.5 / 3.0, 1e-9);
  EXPECT_NEAR(e.gesture.strokes[1].points.front().x_mm, 10.0 * 0.5 / 3.0, 1e-9);
}

TEST(Exploration, ALargeCanvasWidensTheSpacingToBoundTheDuration) {
  const Exploration e = *standard_exploration(1000.0, 800.0);
  EXPECT_GT(e.pass_spacing_mm, 10.0);
  EXPECT_LE(e.duration_s, 120.0 + 1e-9);
  // Beyond about 3 m, even one pass per speed and direction lasts too long.
  EXPECT_TRUE(standard_exploration(1400.0, 1400.0).has_value());
  EXPECT_FALSE(standard_exploration(10000.0, 10000.0).has_value());
}

TEST(Exploration, ATinyCanvasStillGetsAPassAtEverySpeed) {
  const Exploration e = *standard_exploration(2.0, 2.0);
  ASSERT_EQ(e.gesture.strokes.size(), 6u);
  for (const auto& s : e.gesture.strokes) EXPECT_GE(s.points.size(), 2u);
}

TEST(Exploration, TheDescriptionNamesSpacingSpeedsAndDuration) {
  const Exploration e = *standard_exploration(60.0, 110.0);
  const std::string d = describe(e);
  EXPECT_NE(d.find("10 mm apart at 40, 100 and 250 mm/s"), std::string::npos) << d;
}

}  // namespace
}  // namespace vimg::study
