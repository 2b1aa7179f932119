#include "storage/gesture_prediction_csv.hpp"

#include "storage/number_text.hpp"

namespace vimg {

std::string write_predicted_gesture_csv(const std::vector<PredictedGestureRow>& rows) {
  std::string out = "time_s,finger,x_mm,y_mm,predicted_x_mm,predicted_y_mm\n";
  out.reserve(out.size() + rows.size() * 64);
  for (const PredictedGestureRow& r : rows) {
    out += format_decimal(r.time_s) + "," + std::to_string(r.finger) + "," + format_decimal(r.x_mm) + "," +
           format_decimal(r.y_mm) + "," + format_decimal(r.predicted_x_mm) + "," + format_decimal(r.predicted_y_mm) + "\n";
  }
  return out;
}

}  // namespace vimg
