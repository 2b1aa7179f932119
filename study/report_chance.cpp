#include "study/report_chance.hpp"

#include <cmath>

#include "primitives/volume/study_set.hpp"

namespace vimg::study {

namespace {

// The integral of sqrt(u^2 + v^2) over [0, a] x [0, b], a, b >= 0.
double corner_integral(double a, double b) {
  if (a <= 0.0 || b <= 0.0) return 0.0;
  const double r = std::hypot(a, b);
  return a * b * r / 3.0 + a * a * a / 6.0 * std::log((b + r) / a) + b * b * b / 6.0 * std::log((a + r) / b);
}

// The integral over [0, u] x [0, v] with signs: the rectangle between the origin and (u, v).
double signed_corner_integral(double u, double v) {
  const double sign = (u < 0.0) != (v < 0.0) ? -1.0 : 1.0;
  return sign * corner_integral(std::abs(u), std::abs(v));
}

}  // namespace

Workspace study_workspace() {
  static const Workspace workspace = [] {
    const GridGeometry g = make_study_set(0).feature.geometry();
    const Vec3 far_m = g.far_corner_m();
    return Workspace{g.origin_m.x * 1e3, far_m.x * 1e3, g.origin_m.z * 1e3, far_m.z * 1e3};
  }();
  return workspace;
}

double expected_uniform_distance_mm(const Workspace& w, double x_mm, double z_mm) {
  // Far away (a target no study draws, but a file may hold) the four corner terms grow as the cube
  // of the distance and cancel; there the distance to the centre is the expectation to within
  // (size / distance)^2, below 1e-8 relative.
  const double size = std::hypot(w.x_max_mm - w.x_min_mm, w.z_max_mm - w.z_min_mm);
  const double from_centre = std::hypot(x_mm - (w.x_min_mm + w.x_max_mm) / 2.0, z_mm - (w.z_min_mm + w.z_max_mm) / 2.0);
  if (from_centre > 1e4 * size) return from_centre;
  const double u0 = w.x_min_mm - x_mm, u1 = w.x_max_mm - x_mm;
  const double v0 = w.z_min_mm - z_mm, v1 = w.z_max_mm - z_mm;
  const double integral = signed_corner_integral(u1, v1) - signed_corner_integral(u0, v1) -
                          signed_corner_integral(u1, v0) + signed_corner_integral(u0, v0);
  return integral / ((w.x_max_mm - w.x_min_mm) * (w.z_max_mm - w.z_min_mm));
}

}  // namespace vimg::study
