#pragma once
// A gesture: recorded finger paths, kept as strokes, one finger's points from its touch-down to its
// lift. What a gesture file holds (storage/gesture_csv.hpp reads and writes it, spec section 3) and
// what the renderers play; the models and players receive these values, never a file.
#include <vector>

namespace vimg {

struct GesturePoint {
  double time_s = 0.0;
  double x_mm = 0.0;
  double y_mm = 0.0;
  double pressure = 1.0;  // [0, 1]; 1 when the file leaves it empty
};

struct GestureStroke {
  int finger = 0;
  std::vector<GesturePoint> points;  // time never decreasing; first is the down, last the lift
};

struct Gesture {
  std::vector<GestureStroke> strokes;  // ordered by start time
  double start_time_s() const;         // the earliest stroke's first point (0 without points)
  double end_time_s() const;           // the latest stroke's last point (0 without points)
};

// Fingers are numbered 0..kMaxGestureFinger (a protocol-B touch panel's slots).
inline constexpr int kMaxGestureFinger = 63;

}  // namespace vimg
