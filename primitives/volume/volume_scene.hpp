#pragma once
// A volume scene (docs/volume-data.md): which data it shows, how the kinaesthetic part renders it,
// which vibrotactile shaders ride on top with their transfer functions, and the device profile.
// Plain data in file units (mm, ms, N, Hz); storage reads and writes it.
#include <optional>
#include <string>
#include <vector>

#include "primitives/vec3.hpp"
#include "primitives/volume/transfer_function.hpp"

namespace vimg {

struct VolumeDataRef {
  enum class Kind { scalar, vector };
  std::string id;
  Kind kind = Kind::scalar;
  std::string file;  // relative to the scene file
  int source_line = 0;
  friend bool operator==(const VolumeDataRef& a, const VolumeDataRef& b) {
    return a.id == b.id && a.kind == b.kind && a.file == b.file;
  }
};

enum class KinaestheticMode { gradient_force, yielding_surface, vector_guidance };

struct KinaestheticSpec {
  KinaestheticMode mode = KinaestheticMode::vector_guidance;
  std::string data;                     // id of the data it reads
  double scale_N_mm = 0.0;              // gradient force: C in N per (data unit per mm)
  double stiffness_N_per_m = 300.0;     // virtual coupling k_s
  double damping_N_s_per_m = 0.5;       // virtual coupling k_d
  double yield_force_N = 1.5;           // yielding surface
  double friction = 0.3;                // yielding surface, mu
  double min_gradient_per_mm = 0.0;     // yielding surface: weaker gradients are free space
  double across_force_N = 1.5;          // vector guidance
  double follow_force_N = 0.0;          // vector guidance
  friend bool operator==(const KinaestheticSpec&, const KinaestheticSpec&) = default;
};

struct RoughnessSpec {
  std::string data;
  Vec3 direction{0.0, 0.0, 1.0};  // q (normalized when built)
  bool omega_given_as_period = true;           // <period value mm> or <omega value radPerMm>
  std::vector<TransferPoint> omega_points;     // value -> period (mm) or omega (rad/mm)
  std::vector<TransferPoint> amplitude_points; // value -> A (N)
  double full_amplitude_speed_mm_per_s = 30.0;
  friend bool operator==(const RoughnessSpec&, const RoughnessSpec&) = default;
};

struct TransitionCueSpec {
  std::string data;
  double iso_value = 0.0;
  Vec3 direction{0.0, 0.0, 1.0};
  double frequency_hz = 130.0;
  double amplitude_N = 0.3;
  double decay_time_ms = 100.0;
  friend bool operator==(const TransitionCueSpec&, const TransitionCueSpec&) = default;
};

struct DeviceProfile {
  std::string name = "generic";
  double max_force_N = 3.3;
  double max_stiffness_N_per_m = 400.0;
  Vec3 workspace_mm{160.0, 120.0, 120.0};  // full extents, centred on the origin
  double rate_hz = 1000.0;
  double gate_force_N = 0.2;
  double ramp_time_ms = 500.0;
  friend bool operator==(const DeviceProfile&, const DeviceProfile&) = default;
};

struct VolumeScene {
  std::vector<VolumeDataRef> data;
  std::optional<KinaestheticSpec> kinaesthetic;
  std::vector<RoughnessSpec> roughness;
  std::vector<TransitionCueSpec> transition_cues;
  DeviceProfile device;
  friend bool operator==(const VolumeScene&, const VolumeScene&) = default;
};

}  // namespace vimg
