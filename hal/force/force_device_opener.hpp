#pragma once
// Opening the force device a program was asked for, the same way in vimg-force and vimg-probe:
//   "sim"        the simulated device the scene's device profile describes, its hand following a
//                scripted path (or resting at the workspace centre);
//   "hid"        the first HID device that answers the HID force protocol (hidapi enumeration);
//   "hid:PATH"   that hidraw node.
// And the haptic loop's settings for a scene's device profile.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hal/force/simulated_force_device.hpp"
#include "player/haptic/haptic_loop.hpp"
#include "primitives/volume/volume_scene.hpp"
#include "storage/diagnostic.hpp"

namespace vimg {

struct OpenedForceDevice {
  std::unique_ptr<ForceDevice> device;  // null on failure
  std::string description;              // e.g. "hid /dev/hidraw3 (1209:f0ce DIY arm)"
  std::string error;                    // why it failed, with what was found
};

// `device` is "sim", "hid" or "hid:PATH"; `hand` is the simulated hand's path (sim only).
OpenedForceDevice open_force_device(const std::string& device, const DeviceProfile& profile,
                                    std::vector<HandPathPoint> hand, const std::string& hand_description);

// The simulated hand of `--path FILE`: a probe-path CSV (time_s,x_mm,y_mm,z_mm, read by
// storage/volume/probe_path_io.hpp) as the hand's path, starting at loop time 0; an empty path (the
// hand at rest at the workspace centre) when `file` is empty. Problems go to `diagnostics`; nothing
// on failure, a file without rows included.
std::optional<std::vector<HandPathPoint>> simulated_hand_path(const std::string& file, std::vector<Diagnostic>& diagnostics);

// The haptic loop's settings for a scene's device: its rate, force limit, start-up gate and ramp.
HapticLoopConfig haptic_loop_config(const DeviceProfile& profile, int realtime_priority);

}  // namespace vimg
