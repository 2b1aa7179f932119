#pragma once
// Where the matching test's screens put things, in window pixels (pure; docs/player.md,
// "Matching test"). A header strip at the top (the text), a footer strip at the bottom (the
// training thumbnails, the Answer button) and the stage between them, where the image under the
// finger sits at true size, centred: in training and while rubbing it is at the same place, so the
// participant rubs the trial's invisible image exactly where the training picture was.
// At answer time the set's pictures fill stage and footer as on printed sheets: one common scale
// for all of them (their sizes compare as on paper), at most true size, each with its name below.
#include <cstddef>
#include <utility>
#include <vector>

namespace vimg::player_app {

struct PixelRect {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  bool contains(double px, double py) const { return px >= x && py >= y && px < x + w && py < y + h; }
};

struct StudyLayout {
  PixelRect header;
  PixelRect stage;
  PixelRect footer;
  PixelRect answer_button;  // centred in the footer
};

inline constexpr double kStudyHeaderPx = 56.0;
inline constexpr double kStudyFooterPx = 150.0;
inline constexpr double kStudyLabelPx = 30.0;   // a picture's name below it
inline constexpr double kStudyMarginPx = 12.0;  // around each picture cell's content

StudyLayout study_layout(int width_px, int height_px);

// The canvas of a width_mm x height_mm image at true size (px_per_mm), centred in `stage`, its
// corner on whole pixels (so the picture's pixels are the PNG export's).
PixelRect canvas_in_stage(const PixelRect& stage, double width_mm, double height_mm, double px_per_mm);

// One picture placed on a grid of cells: the whole cell (what a tap selects), the picture's
// rectangle (whole pixels at its corner) and the line for its name.
struct PicturePlacement {
  PixelRect cell;
  PixelRect picture;
  PixelRect label;
};
struct PictureGrid {
  double px_per_mm = 0.0;  // the common scale
  std::vector<PicturePlacement> pictures;
};

// The pictures (sizes in mm, in set order) on the grid of columns x rows that gives them the
// largest common scale within `area`, capped at `max_px_per_mm`. Row-major, centred in their cells.
PictureGrid picture_grid(const PixelRect& area, const std::vector<std::pair<double, double>>& sizes_mm,
                         double max_px_per_mm);

// The training thumbnails: one row across the footer.
PictureGrid thumbnail_row(const PixelRect& footer, const std::vector<std::pair<double, double>>& sizes_mm);

// The index of the cell at (px, py), or the count when none.
std::size_t picture_at(const PictureGrid& grid, double px, double py);

}  // namespace vimg::player_app
