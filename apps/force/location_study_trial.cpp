#include "apps/force/location_study_trial.hpp"

#include <cmath>

namespace vimg::force_app {

VolumeScene location_trial_scene(const StudySet& set, LocationMetaphor metaphor) {
  VolumeScene scene = set.scene;
  if (metaphor == LocationMetaphor::roughness) {
    scene.transition_cues.clear();
  } else {
    scene.roughness.clear();
  }
  return scene;
}

std::unique_ptr<HapticScene> build_location_trial_scene(const StudySet& set, LocationMetaphor metaphor) {
  LoadedVolumeScene loaded;
  loaded.scene = location_trial_scene(set, metaphor);
  loaded.scalars["feature"] = std::make_shared<const ScalarGrid>(set.feature);
  loaded.vectors["flow"] = std::make_shared<const VectorGrid>(set.flow);
  return build_haptic_scene(loaded);
}

std::unique_ptr<HapticScene> build_resting_scene(const DeviceProfile& device) {
  return std::make_unique<HapticScene>(device, std::vector<std::shared_ptr<const void>>{},
                                       std::vector<std::shared_ptr<const ForceShader>>{},
                                       std::vector<std::shared_ptr<const ForceShader>>{});
}

DeviceProfile location_study_device() { return make_study_set(1).scene.device; }

LocationTrial location_trial_row(const LocationTrialInput& in) {
  LocationTrial row;
  row.participant = in.participant;
  row.trial = in.trial;
  row.metaphor = in.metaphor;
  row.seed = in.seed;
  row.target_x_mm = in.layout.bend_x_mm;
  row.target_z_mm = in.layout.plane_z_mm;
  row.mark_x_mm = in.mark_m.x * 1e3;
  row.mark_y_mm = in.mark_m.y * 1e3;
  row.mark_z_mm = in.mark_m.z * 1e3;
  row.error_mm = std::hypot(row.mark_x_mm - row.target_x_mm, row.mark_z_mm - row.target_z_mm);
  row.explore_s = in.explore_s;
  row.time_utc = in.time_utc;
  return row;
}

}  // namespace vimg::force_app
