#include "apps/vimg-player/study_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vimg::player_app {

namespace {

// The largest scale at which every picture fits a cell of cell_w x cell_h (margin and label inside).
double fit_scale(double cell_w, double cell_h, const std::vector<std::pair<double, double>>& sizes_mm) {
  const double room_w = cell_w - 2.0 * kStudyMarginPx;
  const double room_h = cell_h - 2.0 * kStudyMarginPx - kStudyLabelPx;
  if (room_w <= 0.0 || room_h <= 0.0) return 0.0;
  double scale = std::numeric_limits<double>::infinity();
  for (const auto& [w, h] : sizes_mm) scale = std::min({scale, room_w / w, room_h / h});
  return scale;
}

PictureGrid place(const PixelRect& area, std::size_t columns, double scale,
                  const std::vector<std::pair<double, double>>& sizes_mm) {
  const std::size_t n = sizes_mm.size();
  const std::size_t rows = (n + columns - 1) / columns;
  const double cell_w = area.w / static_cast<double>(columns);
  const double cell_h = area.h / static_cast<double>(rows);
  PictureGrid grid;
  grid.px_per_mm = scale;
  for (std::size_t i = 0; i < n; ++i) {
    PicturePlacement p;
    const std::size_t row = i / columns, column = i % columns;
    // A last row that is not full is centred.
    const std::size_t in_row = std::min(columns, n - row * columns);
    const double row_offset = (static_cast<double>(columns - in_row) * cell_w) / 2.0;
    p.cell = {area.x + row_offset + static_cast<double>(column) * cell_w, area.y + static_cast<double>(row) * cell_h,
              cell_w, cell_h};
    const double w = sizes_mm[i].first * scale, h = sizes_mm[i].second * scale;
    const double content_h = h + kStudyLabelPx;
    p.picture = {std::round(p.cell.x + (cell_w - w) / 2.0), std::round(p.cell.y + (cell_h - content_h) / 2.0), w, h};
    p.label = {p.cell.x, p.picture.y + h, cell_w, kStudyLabelPx};
    grid.pictures.push_back(p);
  }
  return grid;
}

}  // namespace

StudyLayout study_layout(int width_px, int height_px) {
  const double w = std::max(1, width_px), h = std::max(1, height_px);
  const double header = std::min(kStudyHeaderPx, h / 4.0);
  const double footer = std::min(kStudyFooterPx, h / 4.0);
  StudyLayout layout;
  layout.header = {0.0, 0.0, w, header};
  layout.footer = {0.0, h - footer, w, footer};
  layout.stage = {0.0, header, w, h - header - footer};
  const double button_w = std::min(260.0, w - 2.0 * kStudyMarginPx);
  const double button_h = std::min(84.0, footer - 2.0 * kStudyMarginPx);
  layout.answer_button = {std::round((w - button_w) / 2.0), std::round(layout.footer.y + (footer - button_h) / 2.0),
                          button_w, button_h};
  return layout;
}

PixelRect canvas_in_stage(const PixelRect& stage, double width_mm, double height_mm, double px_per_mm) {
  const double w = width_mm * px_per_mm, h = height_mm * px_per_mm;
  return {std::round(stage.x + (stage.w - w) / 2.0), std::round(stage.y + (stage.h - h) / 2.0), w, h};
}

PictureGrid picture_grid(const PixelRect& area, const std::vector<std::pair<double, double>>& sizes_mm,
                         double max_px_per_mm) {
  const std::size_t n = sizes_mm.size();
  if (n == 0) return {};
  std::size_t best_columns = 1;
  double best_scale = -1.0;
  for (std::size_t columns = 1; columns <= n; ++columns) {
    const std::size_t rows = (n + columns - 1) / columns;
    const double scale =
        fit_scale(area.w / static_cast<double>(columns), area.h / static_cast<double>(rows), sizes_mm);
    if (scale > best_scale) {
      best_scale = scale;
      best_columns = columns;
    }
  }
  return place(area, best_columns, std::clamp(best_scale, 0.0, max_px_per_mm), sizes_mm);
}

PictureGrid thumbnail_row(const PixelRect& footer, const std::vector<std::pair<double, double>>& sizes_mm) {
  const std::size_t n = sizes_mm.size();
  if (n == 0) return {};
  const double scale = fit_scale(footer.w / static_cast<double>(n), footer.h, sizes_mm);
  return place(footer, n, std::max(0.0, scale), sizes_mm);
}

std::size_t picture_at(const PictureGrid& grid, double px, double py) {
  for (std::size_t i = 0; i < grid.pictures.size(); ++i) {
    if (grid.pictures[i].cell.contains(px, py)) return i;
  }
  return grid.pictures.size();
}

}  // namespace vimg::player_app
