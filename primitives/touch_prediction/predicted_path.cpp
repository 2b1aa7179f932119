#include "primitives/touch_prediction/predicted_path.hpp"

#include <cmath>

namespace vimg {

namespace {


const FingerHistory::Point& newest(const FingerHistory& h) { return h.points[static_cast<std::size_t>(h.newest)]; }

PredictedPosition minus(const PredictedPosition& p, const FingerHistory::Point& last) {
  return {p.x_mm - last.x_mm, p.y_mm - last.y_mm};
}

}  // namespace

void reset_predicted_path(PredictedPath& path) {
  path.valid = false;
  path.predictions = 0;
}

PredictedPosition predicted_path_update(PredictedPath& path, const FingerHistory& history, double now_s,
                                        double ahead_s, TouchPredictionModel model, double interval_s) {
  if (history.count == 0) return {};
  if (!(interval_s > 0.0) || !std::isfinite(interval_s) || !std::isfinite(ahead_s)) {
    ++path.predictions;
    return predict_finger_at(history, now_s, ahead_s, model);
  }
  const FingerHistory::Point& last = newest(history);
  const double silence_s = std::max(0.0, now_s - last.time_s);
  const double fade = std::clamp((kSilenceStop_s - silence_s) / (kSilenceStop_s - kSilenceHold_s), 0.0, 1.0);
  if (fade <= 0.0) return {last.x_mm, last.y_mm};
  const bool same = path.valid && path.ahead_s == ahead_s && path.model == model && path.interval_s == interval_s;
  if (!same || silence_s < path.from_s || silence_s > path.to_s) {
    if (same && silence_s > path.to_s && silence_s <= path.to_s + interval_s) {
      path.from_s = path.to_s;  // the next span: its start is the previous end
      path.from_offset_mm = path.to_offset_mm;
      path.to_s = std::min(path.from_s + interval_s, kSilenceStop_s);
      path.to_offset_mm = minus(predict_finger(history, path.to_s + ahead_s, model), last);
      path.predictions += 1;
    } else {
      path.from_s = silence_s;
      path.to_s = std::min(silence_s + interval_s, kSilenceStop_s);
      const auto ends = predict_finger_pair(history, silence_s + ahead_s, path.to_s + ahead_s, model);
      path.from_offset_mm = minus(ends[0], last);
      path.to_offset_mm = minus(ends[1], last);
      path.predictions += 2;
    }
    const double length_s = path.to_s - path.from_s;
    path.slope_mm_per_s = length_s > 0.0 ? PredictedPosition{(path.to_offset_mm.x_mm - path.from_offset_mm.x_mm) / length_s,
                                                             (path.to_offset_mm.y_mm - path.from_offset_mm.y_mm) / length_s}
                                         : PredictedPosition{};
    path.valid = true;
    path.ahead_s = ahead_s;
    path.interval_s = interval_s;
    path.model = model;
    path.last = last;
  }
  const double d = silence_s - path.from_s;
  return {last.x_mm + fade * (path.from_offset_mm.x_mm + d * path.slope_mm_per_s.x_mm),
          last.y_mm + fade * (path.from_offset_mm.y_mm + d * path.slope_mm_per_s.y_mm)};
}

}  // namespace vimg
