#include "player/haptic/haptic_scene.hpp"

#include "primitives/cues/roughness_shader.hpp"
#include "primitives/cues/transition_cue_shader.hpp"
#include "primitives/kinaesthetic/gradient_force.hpp"
#include "primitives/kinaesthetic/vector_guidance.hpp"
#include "primitives/kinaesthetic/yielding_surface.hpp"
#include "primitives/volume/data_fields.hpp"
#include "primitives/volume/modulated_shader.hpp"

namespace vimg {
namespace {

std::vector<const ForceShader*> raw(const std::vector<std::shared_ptr<const ForceShader>>& shaders) {
  std::vector<const ForceShader*> out;
  for (const auto& s : shaders) out.push_back(s.get());
  return out;
}

// File transfer points are in mm; omega output in rad/mm or a period in mm -> SI.
TransferFunction omega_transfer(const RoughnessSpec& r) {
  std::vector<TransferPoint> points = r.omega_points;
  for (auto& p : points) p.output = r.omega_given_as_period ? p.output * 1e-3 : p.output * 1e3;
  return TransferFunction(std::move(points));
}

}  // namespace

HapticScene::HapticScene(DeviceProfile device, std::vector<std::shared_ptr<const void>> keep_alive,
                         std::vector<std::shared_ptr<const ForceShader>> kinaesthetic,
                         std::vector<std::shared_ptr<const ForceShader>> vibrotactile)
    : device_(std::move(device)),
      keep_alive_(std::move(keep_alive)),
      kinaesthetic_(std::move(kinaesthetic)),
      vibrotactile_(std::move(vibrotactile)),
      feedback_(raw(kinaesthetic_), raw(vibrotactile_)) {}

std::unique_ptr<HapticScene> build_haptic_scene(const LoadedVolumeScene& loaded) {
  const VolumeScene& scene = loaded.scene;
  std::vector<std::shared_ptr<const void>> keep;
  std::vector<std::shared_ptr<const ForceShader>> kin, vib;
  auto scalar = [&](const std::string& id) -> std::shared_ptr<const ScalarGrid> {
    const auto it = loaded.scalars.find(id);
    return it == loaded.scalars.end() ? nullptr : it->second;
  };
  if (const auto& k = scene.kinaesthetic) {
    const CouplingParams coupling{k->stiffness_N_per_m, k->damping_N_s_per_m};
    if (k->mode == KinaestheticMode::vector_guidance) {
      const auto it = loaded.vectors.find(k->data);
      if (it != loaded.vectors.end()) {
        keep.push_back(it->second);
        kin.push_back(std::make_shared<VectorGuidanceShader>(
            *it->second, VectorGuidanceParams{coupling, k->across_force_N, k->follow_force_N, 1e-6}));
      }
    } else if (auto field = scalar(k->data)) {
      keep.push_back(field);
      if (k->mode == KinaestheticMode::gradient_force) {
        // C in N per (unit/mm) -> N per (unit/m).
        kin.push_back(std::make_shared<GradientForceShader>(*field, k->scale_N_mm * 1e-3));
      } else {
        kin.push_back(std::make_shared<YieldingSurfaceShader>(
            *field, YieldingSurfaceParams{coupling, k->yield_force_N, k->friction, k->min_gradient_per_mm * 1e3}));
      }
    }
  }
  for (const auto& r : scene.roughness) {
    auto field = scalar(r.data);
    if (!field) continue;
    auto frequency = std::make_shared<MappedSpatialFrequency>(
        field, omega_transfer(r),
        r.omega_given_as_period ? MappedSpatialFrequency::Output::period_m : MappedSpatialFrequency::Output::omega_rad_per_m);
    // The roughness shader renders unit amplitude; the data sets A through the gain field.
    RoughnessParams params;
    params.direction = normalized(r.direction);
    params.amplitude_N = 1.0;
    params.full_amplitude_speed_m_per_s = r.full_amplitude_speed_mm_per_s * 1e-3;
    auto roughness = std::make_shared<RoughnessShader>(frequency, params);
    auto amplitude = std::make_shared<MappedValueField>(field, TransferFunction(r.amplitude_points));
    vib.push_back(std::make_shared<ModulatedShader>(roughness, amplitude));
  }
  for (const auto& c : scene.transition_cues) {
    auto field = scalar(c.data);
    if (!field) continue;
    TransitionCueParams params;
    params.iso_value = c.iso_value;
    params.direction = normalized(c.direction);
    params.frequency_hz = c.frequency_hz;
    params.amplitude_N = c.amplitude_N;
    params.decay_time_s = c.decay_time_ms * 1e-3;
    vib.push_back(std::make_shared<TransitionCueShader>(std::make_shared<VolumeValueField>(field), params));
  }
  return std::make_unique<HapticScene>(scene.device, std::move(keep), std::move(kin), std::move(vib));
}

}  // namespace vimg
