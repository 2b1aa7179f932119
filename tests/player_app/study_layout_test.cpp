// Where the matching test's screens put things (apps/vimg-player/study_layout.hpp).
#include "apps/vimg-player/study_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vimg::player_app {
namespace {

bool inside(const PixelRect& inner, const PixelRect& outer) {
  return inner.x >= outer.x - 1e-9 && inner.y >= outer.y - 1e-9 && inner.x + inner.w <= outer.x + outer.w + 1e-9 &&
         inner.y + inner.h <= outer.y + outer.h + 1e-9;
}

TEST(StudyLayout, HeaderStageAndFooterTileTheWindow) {
  const StudyLayout l = study_layout(1024, 768);
  EXPECT_EQ(l.header.y, 0.0);
  EXPECT_EQ(l.stage.y, l.header.h);
  EXPECT_EQ(l.footer.y, l.stage.y + l.stage.h);
  EXPECT_EQ(l.footer.y + l.footer.h, 768.0);
  EXPECT_TRUE(inside(l.answer_button, l.footer));
  EXPECT_TRUE(l.answer_button.contains(512, l.footer.y + l.footer.h / 2));
}

TEST(StudyLayout, TheCanvasIsCentredAtTrueSizeOnWholePixels) {
  const StudyLayout l = study_layout(1024, 768);
  const PixelRect c = canvas_in_stage(l.stage, 60.0, 110.0, 3.0);
  EXPECT_EQ(c.w, 180.0);
  EXPECT_EQ(c.h, 330.0);
  EXPECT_EQ(c.x, std::round(c.x));
  EXPECT_EQ(c.y, std::round(c.y));
  EXPECT_NEAR(c.x + c.w / 2, 512.0, 0.5);
  EXPECT_NEAR(c.y + c.h / 2, l.stage.y + l.stage.h / 2, 0.5);
}

TEST(StudyLayout, AnswerSheetsShareTheLargestScaleThatFitsAndNeverExceedTrueSize) {
  const PixelRect area{0, 56, 1024, 712};
  const std::vector<std::pair<double, double>> tall(4, {60.0, 110.0});
  const PictureGrid grid = picture_grid(area, tall, 100.0);
  ASSERT_EQ(grid.pictures.size(), 4u);
  // Four tall sheets side by side beat 2 x 2 on a landscape window.
  EXPECT_EQ(grid.pictures[0].cell.y, grid.pictures[3].cell.y);
  for (const auto& p : grid.pictures) {
    EXPECT_TRUE(inside(p.picture, p.cell));
    EXPECT_TRUE(inside(p.label, p.cell));
    EXPECT_NEAR(p.picture.w, 60.0 * grid.px_per_mm, 1e-9);
    EXPECT_GE(p.label.y, p.picture.y + p.picture.h - 1e-9);
  }
  EXPECT_NEAR(grid.px_per_mm, (1024.0 / 4 - 2 * kStudyMarginPx) / 60.0, 1e-9);  // the width limits
  EXPECT_EQ(picture_grid(area, tall, 3.0).px_per_mm, 3.0);  // capped at true size
  // Wide sheets on a portrait window stack.
  const std::vector<std::pair<double, double>> wide(4, {110.0, 60.0});
  const PictureGrid stacked = picture_grid(PixelRect{0, 0, 600, 1000}, wide, 100.0);
  EXPECT_EQ(stacked.pictures[0].cell.x, stacked.pictures[1].cell.x);
}

TEST(StudyLayout, ALastRowThatIsNotFullIsCentredAndTapsFindTheirCell) {
  const std::vector<std::pair<double, double>> square(3, {50.0, 50.0});
  const PictureGrid grid = picture_grid(PixelRect{0, 0, 400, 400}, square, 100.0);
  ASSERT_EQ(grid.pictures.size(), 3u);
  EXPECT_EQ(grid.pictures[0].cell.w, 200.0);  // 2 x 2
  EXPECT_EQ(grid.pictures[2].cell.x, 100.0);  // the third centred below
  EXPECT_EQ(picture_at(grid, 150, 300), 2u);
  EXPECT_EQ(picture_at(grid, 50, 300), 3u);  // beside it: nothing
  EXPECT_EQ(picture_at(grid, 250, 50), 1u);
}

TEST(StudyLayout, ThumbnailsStayInOneRowOfTheFooter) {
  const StudyLayout l = study_layout(1024, 768);
  const std::vector<std::pair<double, double>> sizes{{60, 110}, {60, 110}, {100, 60}, {60, 110}};
  const PictureGrid row = thumbnail_row(l.footer, sizes);
  ASSERT_EQ(row.pictures.size(), 4u);
  for (const auto& p : row.pictures) {
    EXPECT_EQ(p.cell.y, l.footer.y);
    EXPECT_TRUE(inside(p.picture, l.footer));
  }
  EXPECT_GT(row.px_per_mm, 0.5);
}

}  // namespace
}  // namespace vimg::player_app
