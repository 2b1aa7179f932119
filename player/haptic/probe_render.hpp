#pragma once
// Offline rendering of a scripted probe path through a scene, as the haptic loop would render
// it with a perfectly stiff hand: the probe is the path, resampled at rate_hz by linear
// interpolation (velocity from the path segment), and each step sums the scene's shaders and
// clamps once to max_force_N. No start-up gating: the first row is the scene's own force.
#include <vector>

#include "player/haptic/haptic_scene.hpp"
#include "storage/volume/probe_path_io.hpp"

namespace vimg {

std::vector<ProbeForceRow> render_probe_path(HapticScene& scene, const std::vector<ProbePathPoint>& path,
                                             double rate_hz, double max_force_N);

}  // namespace vimg
