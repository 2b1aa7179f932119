#pragma once
// The canvas view: millimetres on the page to pixels on the screen, at physical scale times zoom.
#include "primitives/image.hpp"

namespace vimg::editor {

struct Point2Px {
  float x = 0.0f;
  float y = 0.0f;
};

class Viewport {
 public:
  // `screen_px_per_mm`: the display's physical density (96 dpi is 3.78 px/mm).
  explicit Viewport(double screen_px_per_mm = 96.0 / 25.4) : screen_px_per_mm_(screen_px_per_mm) {}

  void set_origin_px(float x, float y) { origin_x_px_ = x; origin_y_px_ = y; }
  double zoom() const { return zoom_; }
  void set_zoom(double zoom);
  // Zooms by `factor` keeping the page point under (x, y) px in place.
  void zoom_at(double factor, float x_px, float y_px);
  void pan_px(float dx, float dy) { pan_x_px_ += dx; pan_y_px_ += dy; }
  void reset_pan() { pan_x_px_ = 0; pan_y_px_ = 0; }
  double px_per_mm() const { return screen_px_per_mm_ * zoom_; }

  Point2Px to_px(Point2Mm p) const;
  Point2Mm to_mm(Point2Px p) const;
  float length_px(double mm) const { return static_cast<float>(mm * px_per_mm()); }

  // Where page (0, 0) is on screen.
  Point2Px page_origin_px() const { return to_px(Point2Mm{0, 0}); }

  static constexpr double kMinZoom = 0.05;
  static constexpr double kMaxZoom = 50.0;

 private:
  double screen_px_per_mm_;
  double zoom_ = 1.0;
  float origin_x_px_ = 0;
  float origin_y_px_ = 0;
  float pan_x_px_ = 0;
  float pan_y_px_ = 0;
};

// A ruler/grid step in mm that gives at least `min_px` between lines: 1, 2, 5, 10, 20, 50, ...
double grid_step_mm(double px_per_mm, double min_px);

}  // namespace vimg::editor
