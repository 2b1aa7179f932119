#pragma once
// The file `vimg gesture predict` writes (docs/latency.md): a header, then one row per input row,
//   time_s,finger,x_mm,y_mm,predicted_x_mm,predicted_y_mm
// numbers as the gesture file writes them (shortest text that reads back exactly).
#include <string>
#include <vector>

namespace vimg {

struct PredictedGestureRow {
  double time_s = 0.0;
  int finger = 0;
  double x_mm = 0.0;
  double y_mm = 0.0;
  double predicted_x_mm = 0.0;
  double predicted_y_mm = 0.0;
};

std::string write_predicted_gesture_csv(const std::vector<PredictedGestureRow>& rows);

}  // namespace vimg
