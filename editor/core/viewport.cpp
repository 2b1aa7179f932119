#include "editor/core/viewport.hpp"

#include <algorithm>

namespace vimg::editor {

void Viewport::set_zoom(double zoom) { zoom_ = std::clamp(zoom, kMinZoom, kMaxZoom); }

void Viewport::zoom_at(double factor, float x_px, float y_px) {
  const Point2Mm anchor = to_mm(Point2Px{x_px, y_px});
  set_zoom(zoom_ * factor);
  const Point2Px moved = to_px(anchor);
  pan_x_px_ += x_px - moved.x;
  pan_y_px_ += y_px - moved.y;
}

Point2Px Viewport::to_px(Point2Mm p) const {
  return Point2Px{origin_x_px_ + pan_x_px_ + static_cast<float>(p.x_mm * px_per_mm()),
                  origin_y_px_ + pan_y_px_ + static_cast<float>(p.y_mm * px_per_mm())};
}

Point2Mm Viewport::to_mm(Point2Px p) const {
  return Point2Mm{static_cast<double>(p.x - origin_x_px_ - pan_x_px_) / px_per_mm(),
                  static_cast<double>(p.y - origin_y_px_ - pan_y_px_) / px_per_mm()};
}

double grid_step_mm(double px_per_mm, double min_px) {
  static constexpr double kSteps[] = {1, 2, 5};
  double decade = 0.1;
  for (int i = 0; i < 8; ++i, decade *= 10) {
    for (double s : kSteps) {
      if (s * decade * px_per_mm >= min_px) return s * decade;
    }
  }
  return 10000.0;
}

}  // namespace vimg::editor
