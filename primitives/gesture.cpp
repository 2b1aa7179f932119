#include "primitives/gesture.hpp"

#include <algorithm>
#include <utility>

namespace vimg {

namespace {

// The earliest first point and the latest last point of the strokes that have points; {0, 0} without.
std::pair<double, double> time_span(const std::vector<GestureStroke>& strokes) {
  std::pair<double, double> span{0.0, 0.0};
  bool any = false;
  for (const GestureStroke& s : strokes) {
    if (s.points.empty()) continue;
    const double first = s.points.front().time_s, last = s.points.back().time_s;
    span = any ? std::pair{std::min(span.first, first), std::max(span.second, last)} : std::pair{first, last};
    any = true;
  }
  return span;
}

}  // namespace

double Gesture::start_time_s() const { return time_span(strokes).first; }

double Gesture::end_time_s() const { return time_span(strokes).second; }

}  // namespace vimg
