#pragma once
// Chance in the location study (docs/studies.md "Chance"): the expected x-z distance from a mark
// placed uniformly at random in the workspace to a trial's target, in closed form. For a point p and
// the rectangle [x0, x1] x [z0, z1] with u = x - p.x, v = z - p.z,
//
//   E|mark - p| = (1 / area) * sum over the four corners of +-H(u_corner, v_corner), where
//   H(u, v) = sgn(u) sgn(v) G(|u|, |v|) = the integral of sqrt(u'^2 + v'^2) over [0, u] x [0, v], and
//   G(a, b) = a b r / 3 + a^3/6 ln((b + r)/a) + b^3/6 ln((a + r)/b),  r = sqrt(a^2 + b^2)   (G = 0 if a or b is 0).
//
// The report's chance is the mean of that over the trials' targets. The mark's y does not enter (the
// intersection is a line along y). For the study's workspace (x +-80, z +-60 mm) a target at the centre
// gives 53.9 mm, the paper's "about 53 mm"; targets spread as the data set draws them give about 59 mm.
#include <vector>

namespace vimg::study {

struct Workspace {
  double x_min_mm = 0.0, x_max_mm = 0.0;
  double z_min_mm = 0.0, z_max_mm = 0.0;
};

// The box of the location study's data set (primitives/volume/study_set.hpp, make_study_set): the
// extent of its volume grids in x and z.
Workspace study_workspace();

// The expected x-z distance from a uniform point of `workspace` to (x_mm, z_mm); the point may lie
// anywhere, inside or outside (beyond 10^4 workspace diagonals, the distance to the centre, which
// the expectation approaches to within 1e-8 relative). The workspace must have a positive area.
double expected_uniform_distance_mm(const Workspace& workspace, double x_mm, double z_mm);

}  // namespace vimg::study
