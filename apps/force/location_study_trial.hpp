#pragma once
// One trial of the volume paper's location study (section 5), without devices or threads: the data
// set of the trial's seed, the scene the participant feels, the target, and the row the trial file
// gets (storage/study/trial_table.hpp).
//
// The target. The flow turns over 20 mm of x centred on bend_x (primitives/volume/study_set.hpp), so
// the bend is the slab |x - bend_x| <= 10 mm, the same at every y and z; the feature is the plane
// z = plane_z. The paper measures "the distance between the subject's mark and the centre of the
// feature", in 2D, "since both features are defined in single orthogonal dimensions, the intersection
// is a line in 3D": the centre of the bend (x = bend_x, where the flow has turned half way, 22.5
// degrees) meets the plane in the line x = bend_x, z = plane_z along y. So
//   target_x_mm = bend_x_mm, target_z_mm = plane_z_mm,
//   error_mm = hypot(mark_x_mm - target_x_mm, mark_z_mm - target_z_mm)   (y plays no part),
// computed from the very numbers the row holds (the mark converted to mm first), so anyone reading
// the file gets error_mm back exactly with std::hypot.
#include <cstdint>
#include <memory>
#include <string>

#include "player/haptic/haptic_scene.hpp"
#include "primitives/volume/study_set.hpp"
#include "storage/study/trial_table.hpp"

namespace vimg::force_app {

// The scene of a trial: the data set's own scene (vector guidance on the flow, the device profile)
// with only the metaphor under test: its roughness or its transition cue, not both.
VolumeScene location_trial_scene(const StudySet& set, LocationMetaphor metaphor);
// That scene built over the set's grids, ready for the haptic loop (the grids are copied into it).
std::unique_ptr<HapticScene> build_location_trial_scene(const StudySet& set, LocationMetaphor metaphor);
// A scene with no shaders: zero force (the safety stack still guards the workspace), between trials.
std::unique_ptr<HapticScene> build_resting_scene(const DeviceProfile& device);

// The device profile of every trial (the data set's: rate, force limit, gate and ramp).
DeviceProfile location_study_device();

struct LocationTrialInput {
  std::string participant;
  int trial = 0;
  LocationMetaphor metaphor = LocationMetaphor::roughness;
  std::uint64_t seed = 0;
  StudyLayout layout;
  Vec3 mark_m;           // the probe at the press
  double explore_s = 0;  // the trial's clock at the press
  std::string time_utc;
};
// The row: target from the layout, mark in mm, error as above.
LocationTrial location_trial_row(const LocationTrialInput& input);

}  // namespace vimg::force_app
