#include "hal/force/force_device_opener.hpp"

#include <cstdio>

#include "hal/force/hid_force_finder.hpp"
#include "storage/volume/probe_path_io.hpp"

namespace vimg {

OpenedForceDevice open_force_device(const std::string& device, const DeviceProfile& profile,
                                    std::vector<HandPathPoint> hand, const std::string& hand_description) {
  OpenedForceDevice opened;
  if (device == "sim") {
    // The simulated device is the one the scene describes.
    ForceDeviceLimits limits;
    limits.max_force_N = profile.max_force_N;
    limits.max_stiffness_N_per_m = profile.max_stiffness_N_per_m;
    limits.workspace_m = profile.workspace_mm * 1e-3;
    if (hand.empty()) hand.push_back({0.0, Vec3{}});  // the workspace centre
    opened.device = std::make_unique<SimulatedForceDevice>(std::move(hand), HandModel{}, limits);
    opened.description = "sim, " + hand_description;
    return opened;
  }
  const std::string path = device.rfind("hid:", 0) == 0 ? device.substr(4) : std::string();
  HidapiTransportHost host;
  HidForceSearch found = find_hid_force_device(host, path);
  if (!found.device) {
    opened.error = found.report;
    return opened;
  }
  char ids[16];
  std::snprintf(ids, sizeof ids, "%04x:%04x", found.opened.vendor_id, found.opened.product_id);
  opened.description =
      "hid " + found.opened.path + " (" + ids + (found.opened.product.empty() ? "" : " " + found.opened.product) + ")";
  opened.device = std::move(found.device);
  return opened;
}

std::optional<std::vector<HandPathPoint>> simulated_hand_path(const std::string& file, std::vector<Diagnostic>& diagnostics) {
  if (file.empty()) return std::vector<HandPathPoint>{};
  const ProbePathParseResult parsed = load_probe_path_file(file);
  diagnostics.insert(diagnostics.end(), parsed.diagnostics.begin(), parsed.diagnostics.end());
  if (!parsed.path || parsed.path->empty()) return std::nullopt;
  std::vector<HandPathPoint> hand;
  hand.reserve(parsed.path->size());
  const double t0 = parsed.path->front().time_s;
  for (const ProbePathPoint& p : *parsed.path) hand.push_back({p.time_s - t0, p.position_m});
  return hand;
}

HapticLoopConfig haptic_loop_config(const DeviceProfile& profile, int realtime_priority) {
  HapticLoopConfig config;
  config.rate_hz = profile.rate_hz;
  config.safety.max_force_N = profile.max_force_N;
  config.safety.gate_force_N = profile.gate_force_N;
  config.safety.ramp_time_s = profile.ramp_time_ms * 1e-3;
  config.realtime_priority = realtime_priority;
  return config;
}

}  // namespace vimg
