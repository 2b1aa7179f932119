#pragma once
// The volume paper's evaluation data set (section 5), generated from a seed:
//   - flow (vector): unit vectors along +x that turn, linearly in angle over 20 mm centred on a
//     random bend_x, into the diagonal (1, 0, 1)/sqrt(2) in the x-z plane;
//   - feature (scalar): the signed distance in mm to a plane z = plane_z at a random z;
//   - a scene: vector guidance on the flow; roughness on the feature with period 0.4 mm far from
//     the plane to 2.5 mm at it and amplitude 0.6 N far to 0.3 N at it, both linear over +-20 mm;
//     a transition cue at the plane (130 Hz, 0.3 N, 100 ms).
// The box is the device workspace of a desktop force device: x +-80, y +-60, z +-60 mm, sampled
// every 2 mm. Both fields are linear between samples where it matters (the scalar everywhere,
// the flow outside the bend), so trilinear sampling reproduces them.
#include <cstdint>

#include "primitives/volume/scalar_grid.hpp"
#include "primitives/volume/vector_grid.hpp"
#include "primitives/volume/volume_scene.hpp"

namespace vimg {

struct StudyLayout {
  double bend_x_mm = 0.0;   // centre of the 20 mm bend, uniform in [-40, 40]
  double plane_z_mm = 0.0;  // the feature plane, uniform in [-30, 30]
};

struct StudySet {
  StudyLayout layout;
  ScalarGrid feature;
  VectorGrid flow;
  VolumeScene scene;  // names "feature.nrrd" and "flow.nrrd"
};

inline constexpr double kStudyBendWidthMm = 20.0;
inline constexpr double kStudyBandHalfWidthMm = 20.0;

StudyLayout study_layout(std::uint64_t seed);
// The flow direction at x (mm) for a bend centred at bend_x_mm.
Vec3 study_flow_direction(double x_mm, double bend_x_mm);
StudySet make_study_set(std::uint64_t seed);

}  // namespace vimg
