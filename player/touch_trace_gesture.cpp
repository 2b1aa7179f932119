#include "player/touch_trace_gesture.hpp"

#include <algorithm>
#include <cmath>

#include "storage/limits.hpp"

namespace vimg {
namespace {

static_assert(kMaxTouchTraceFinger == kMaxGestureFinger, "a recording's fingers are a gesture's fingers");

struct AxisMap {
  double offset = 0.0;
  double mm_per_unit = 1.0;
  double to_mm(double v) const { return (v - offset) * mm_per_unit; }
};

std::string number(double v) {
  std::string s = std::to_string(v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

TraceGestureResult trace_to_gesture(const TouchTrace& trace, const TouchMapping& mapping, const std::string& file_name) {
  TraceGestureResult result;
  const TouchAxis xr = mapping.x_range.value_or(trace.x);
  const TouchAxis yr = mapping.y_range.value_or(trace.y);
  AxisMap mx, my;
  if (mapping.panel_width_mm && mapping.panel_height_mm) {
    if (!xr.known() || !yr.known()) {
      const std::string problem = xr.known() ? touch_axis_problem(yr, "y") : touch_axis_problem(xr, "x");
      result.usage_problem = "--panel-mm needs the digitizer's axis ranges, and " + file_name + " " + problem +
                             "; pass --px-per-mm K instead";
      return result;
    }
    mx = {xr.min, *mapping.panel_width_mm / (xr.max - xr.min)};
    my = {yr.min, *mapping.panel_height_mm / (yr.max - yr.min)};
  } else if (mapping.units_per_mm) {
    mx = {xr.known() ? xr.min : 0.0, 1.0 / *mapping.units_per_mm};
    my = {yr.known() ? yr.min : 0.0, 1.0 / *mapping.units_per_mm};
  } else if (xr.known() && yr.known() && xr.units_per_mm > 0.0 && yr.units_per_mm > 0.0) {
    mx = {xr.min, 1.0 / xr.units_per_mm};
    my = {yr.min, 1.0 / yr.units_per_mm};
  } else {
    result.usage_problem = file_name + " does not give the digitizer's size in mm (no axis resolution); pass --panel-mm WxH " +
                           "(the touch area in mm; the recording's axis ranges map onto it) or --px-per-mm K (digitizer units per mm)";
    return result;
  }
  const TouchAxis& pr = trace.pressure;
  Gesture gesture;
  for (const TouchContact& contact : trace.contacts) {
    GestureStroke stroke;
    stroke.finger = contact.finger;
    for (const TouchSample& s : contact.samples) {
      GesturePoint p;
      p.time_s = s.time_s;
      p.x_mm = mx.to_mm(s.x);
      p.y_mm = my.to_mm(s.y);
      p.pressure = 1.0;
      if (s.pressure && pr.known()) p.pressure = std::clamp((*s.pressure - pr.min) / (pr.max - pr.min), 0.0, 1.0);
      if (std::fabs(p.x_mm) > kMaxGestureCoordinateMm || std::fabs(p.y_mm) > kMaxGestureCoordinateMm) {
        result.errors.push_back(Diagnostic{Diagnostic::Severity::error, file_name, s.line,
                                           "finger " + std::to_string(contact.finger) + " at (" + number(p.x_mm) + ", " +
                                               number(p.y_mm) + ") mm is beyond " + number(kMaxGestureCoordinateMm) +
                                               " mm (limit " + number(kMaxGestureCoordinateMm) + ")"}
                                    .to_string());
        return result;
      }
      stroke.points.push_back(p);
    }
    gesture.strokes.push_back(std::move(stroke));
  }
  std::stable_sort(gesture.strokes.begin(), gesture.strokes.end(), [](const GestureStroke& a, const GestureStroke& b) {
    return a.points.front().time_s < b.points.front().time_s;
  });
  result.gesture = std::move(gesture);
  return result;
}

}  // namespace vimg
